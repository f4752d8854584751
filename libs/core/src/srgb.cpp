#include <rtlab/core/srgb.hpp>

#include <array>
#include <cmath>

namespace rtlab {

float srgb_encode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;  // negatives and NaN
    if (linear >= 1.0f) return 1.0f;
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded) {
    if (!(encoded > 0.0f)) return 0.0f;
    if (encoded >= 1.0f) return 1.0f;
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

std::uint8_t srgb_encode_8bit(float linear) {
    return static_cast<std::uint8_t>(std::lround(srgb_encode(linear) * 255.0f));
}

float srgb_decode_8bit(std::uint8_t code) {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgb_decode(static_cast<float>(i) / 255.0f);
        return t;
    }();
    return table[code];
}

}  // namespace rtlab
