#pragma once
/// \brief The largest image a scene file or a command line may ask for.
#include <cstdint>
#include <string_view>

namespace rtlab {

/// Largest image side and pixel count: 16384 and 2^26 pixels (a 768 MiB float image), so that a typo such
/// as 1e9 is an error rather than an allocation failure.
inline constexpr int kMaxImageSide = 16384;
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 26;

/// Throws rtlab::Error "<what>: ..." unless 1 <= width, height <= kMaxImageSide and width * height <=
/// kMaxImagePixels.
void check_image_size(std::int64_t width, std::int64_t height, std::string_view what = "image size");

}  // namespace rtlab
