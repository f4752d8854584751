#pragma once
/// \brief The sRGB transfer function, in one place for every library.
#include <cstddef>
#include <cstdint>

namespace rtlab {

struct RGB;

/// Linear [0, 1] to sRGB-encoded [0, 1] (IEC 61966-2-1); input is clamped to [0, 1], NaN gives 0.
float srgb_encode(float linear);
/// sRGB-encoded [0, 1] to linear.
float srgb_decode(float encoded);
/// Linear value to an 8-bit sRGB code, rounded to nearest.
std::uint8_t srgb_encode_8bit(float linear);
/// srgb_encode_8bit of every channel of `count` pixels, to 3 * count bytes r, g, b, ...: the same codes, without
/// a call per value (writing a 1280x960 PNG spent 0.14 G instructions in those calls).
void srgb_encode_8bit(const RGB* pixels, std::size_t count, std::uint8_t* out);
/// 8-bit sRGB code to linear, by table (exact to float rounding).
float srgb_decode_8bit(std::uint8_t code);

}  // namespace rtlab
