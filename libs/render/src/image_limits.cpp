#include <rtlab/core/error.hpp>
#include <rtlab/render/image_limits.hpp>

#include <string>

namespace rtlab {

void check_image_size(std::int64_t width, std::int64_t height, std::string_view what) {
    const std::string name(what);
    if (width < 1 || height < 1)
        throw Error(name + ": " + std::to_string(width) + "x" + std::to_string(height) +
                    ": width and height must be at least 1");
    if (width > kMaxImageSide || height > kMaxImageSide)
        throw Error(name + ": " + std::to_string(width) + "x" + std::to_string(height) + " is larger than " +
                    std::to_string(kMaxImageSide) + " pixels per side");
    if (width * height > kMaxImagePixels)
        throw Error(name + ": " + std::to_string(width) + "x" + std::to_string(height) + " is more than " +
                    std::to_string(kMaxImagePixels) + " pixels");
}

}  // namespace rtlab
