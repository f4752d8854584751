#include <rtlab/core/color.hpp>
#include <rtlab/core/srgb.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

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

namespace {

// The exact code, the definition the fast path below reproduces.
int exact_code(float linear) { return static_cast<int>(std::lround(srgb_encode(linear) * 255.0f)); }

// A PNG is written a powf per channel without this (7-12% of a 1280x960 Whitted run). The exact code is a
// staircase in the linear value: `m_lower[k]` is the smallest float whose exact code is at least k (found by
// bisection over the float bit patterns, so the thresholds are those of exact_code itself), and `m_start[c]` the
// exact code at the start of cell c of kCells equal cells of [0, 1). A value then needs its cell and at most a
// step or two up the staircase (the sRGB curve climbs less than one code per cell except near 0). This assumes
// exact_code never steps down as the value grows; tests/core/srgb_test checks every boundary's neighbourhood.
class Encoder8 {
public:
    static constexpr int kCells = 4096;

    Encoder8() {
        m_lower[0] = 0.0f;
        for (int k = 1; k < 256; ++k) {
            std::uint32_t lo = 0, hi = std::bit_cast<std::uint32_t>(1.0f);  // code(lo) < k <= code(hi)
            while (hi - lo > 1) {
                const std::uint32_t mid = lo + (hi - lo) / 2;
                (exact_code(std::bit_cast<float>(mid)) >= k ? hi : lo) = mid;
            }
            m_lower[k] = std::bit_cast<float>(hi);
        }
        m_lower[256] = std::numeric_limits<float>::infinity();  // stops the climb at 255
        for (int c = 0; c < kCells; ++c)
            m_start[c] = static_cast<std::uint8_t>(exact_code(static_cast<float>(c) / static_cast<float>(kCells)));
    }

    std::uint8_t encode(float linear) const {
        if (!(linear > 0.0f)) return 0;  // negatives and NaN
        if (linear >= 1.0f) return 255;
        // linear * kCells is exact (a power of two), so the cell's start is never above the value.
        int code = m_start[static_cast<int>(linear * static_cast<float>(kCells))];
        while (linear >= m_lower[code + 1]) ++code;
        return static_cast<std::uint8_t>(code);
    }

private:
    std::array<float, 257> m_lower{};
    std::array<std::uint8_t, kCells> m_start{};
};

}  // namespace

namespace {
const Encoder8& encoder8() {
    static const Encoder8 encoder;
    return encoder;
}
}  // namespace

std::uint8_t srgb_encode_8bit(float linear) { return encoder8().encode(linear); }

void srgb_encode_8bit(const RGB* pixels, std::size_t count, std::uint8_t* out) {
    const Encoder8& encoder = encoder8();
    for (std::size_t i = 0; i < count; ++i) {
        out[3 * i] = encoder.encode(pixels[i].r);
        out[3 * i + 1] = encoder.encode(pixels[i].g);
        out[3 * i + 2] = encoder.encode(pixels[i].b);
    }
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
