#pragma once
/// \brief The sRGB transfer function, in one place for every library.
#include <cstdint>

namespace rtlab {

/// Linear [0, 1] to sRGB-encoded [0, 1] (IEC 61966-2-1); input is clamped to [0, 1], NaN gives 0.
float srgb_encode(float linear);
/// sRGB-encoded [0, 1] to linear.
float srgb_decode(float encoded);
/// Linear value to an 8-bit sRGB code, rounded to nearest.
std::uint8_t srgb_encode_8bit(float linear);
/// 8-bit sRGB code to linear, by table (exact to float rounding).
float srgb_decode_8bit(std::uint8_t code);

}  // namespace rtlab
