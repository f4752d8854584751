#pragma once
/// \brief An image looked up by uv: bilinear or nearest filtering, wrap modes, uv scale and offset.
#include <rtlab/core/image.hpp>
#include <rtlab/textures/texture.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string_view>

namespace rtlab {

/// What happens outside [0, 1]: repeat the image, clamp to the edge texels, or repeat mirrored.
enum class WrapMode { repeat, clamp, mirror };
enum class ImageFilter { bilinear, nearest };

/// "repeat", "clamp", "mirror"; anything else throws rtlab::Error naming what was given.
WrapMode parse_wrap_mode(std::string_view name);

struct ImageTextureOptions {
    WrapMode wrap = WrapMode::repeat;
    ImageFilter filter = ImageFilter::bilinear;
    Vec2 scale{1.0f};   ///< uv' = uv * scale + offset, then looked up
    Vec2 offset{0.0f};
};

/// \brief Image texture. Texel (x, y) covers u in [x/W, (x+1)/W] and v in [1-(y+1)/H, 1-y/H]: u to the
/// right, v up, so v = 0 is the image's bottom row (the OpenGL / pbrt convention). Bilinear filtering
/// interpolates between texel centres, wrapping the neighbours with the wrap mode. Non-finite uv gives black.
class ImageTexture final : public Texture {
public:
    /// The image must not be empty. 8-bit files are already linear here (read_image decodes sRGB).
    explicit ImageTexture(std::shared_ptr<const Image> image, const ImageTextureOptions& options = {});
    /// Loads with rtlab::read_image; a missing or corrupt file throws rtlab::Error naming it.
    static std::shared_ptr<ImageTexture> load(const std::filesystem::path& path, const ImageTextureOptions& options = {},
                                              ColorEncoding encoding = ColorEncoding::srgb);

    RGB eval(const TextureLookup& lookup) const override { return sample(lookup.uv); }
    RGB sample(Vec2 uv) const;
    const Image& image() const { return *m_image; }

private:
    const RGB& texel(std::int64_t x, std::int64_t y) const;  // texel indices, wrapped here

    std::shared_ptr<const Image> m_image;
    ImageTextureOptions m_options;
};

}  // namespace rtlab
