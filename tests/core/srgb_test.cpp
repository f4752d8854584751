#include <rtlab/core/color.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/core/srgb.hpp>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

using namespace rtlab;

namespace {

int exact_code(float linear) { return static_cast<int>(std::lround(srgb_encode(linear) * 255.0f)); }

}  // namespace

TEST_CASE("srgb_encode_8bit gives the exact formula's code around every 8-bit boundary", "[core][srgb]") {
    // Walk the float bit patterns from 0 to 1: wherever the exact code changes, check 2000 floats either side.
    // Finding the boundaries by bisection (as the encoder does) would share its assumption; this walks up
    // in steps of 2^12 patterns and bisects each step that changes the code, so a step down is seen too.
    const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
    int boundaries = 0;
    std::uint64_t bad = 0;
    for (std::uint32_t b = 0; b < one; b += 4096) {
        const std::uint32_t e = std::min(b + 4096, one);
        if (exact_code(std::bit_cast<float>(b)) == exact_code(std::bit_cast<float>(e))) continue;
        std::uint32_t lo = b, hi = e;
        while (hi - lo > 1) {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            (exact_code(std::bit_cast<float>(mid)) == exact_code(std::bit_cast<float>(b)) ? lo : hi) = mid;
        }
        ++boundaries;
        for (std::uint32_t x = hi > 2000 ? hi - 2000 : 0; x < std::min(hi + 2000, one); ++x) {
            const float f = std::bit_cast<float>(x);
            bad += srgb_encode_8bit(f) != exact_code(f);
        }
    }
    CHECK(boundaries == 255);
    CHECK(bad == 0);
}

TEST_CASE("srgb_encode_8bit matches the exact formula on random values and the special ones", "[core][srgb]") {
    Rng rng(11);
    std::uint64_t bad = 0;
    for (int i = 0; i < 2000000; ++i) {
        // Half uniform in [0, 1), half spread over the exponents (dark values, where codes are dense).
        const float f =
            i % 2 ? rng.uniform() : std::bit_cast<float>(rng.next_u32() % std::bit_cast<std::uint32_t>(1.0f));
        bad += srgb_encode_8bit(f) != exact_code(f);
    }
    CHECK(bad == 0);
    using L = std::numeric_limits<float>;
    CHECK(srgb_encode_8bit(L::quiet_NaN()) == 0);
    CHECK(srgb_encode_8bit(-1.0f) == 0);
    CHECK(srgb_encode_8bit(-0.0f) == 0);
    CHECK(srgb_encode_8bit(L::denorm_min()) == 0);
    CHECK(srgb_encode_8bit(1.0f) == 255);
    CHECK(srgb_encode_8bit(0x1.fffffep-1f) == 255);
    CHECK(srgb_encode_8bit(L::infinity()) == 255);
    CHECK(srgb_encode_8bit(-L::infinity()) == 0);
}

TEST_CASE("srgb_encode_8bit over pixels gives each channel's code in r g b order", "[core][srgb]") {
    using L = std::numeric_limits<float>;
    Rng rng(12);
    std::vector<RGB> pixels = {{L::quiet_NaN(), -1.0f, 1.0f},
                               {L::infinity(), -L::infinity(), 0x1.fffffep-1f},
                               {0.0031308f, 0.5f, L::denorm_min()}};
    for (int i = 0; i < 100000; ++i) pixels.emplace_back(rng.uniform(), rng.uniform() * 1.5f - 0.25f, rng.uniform());
    std::vector<std::uint8_t> codes(3 * pixels.size(), 77);
    srgb_encode_8bit(pixels.data(), pixels.size(), codes.data());
    std::uint64_t bad = 0;
    for (std::size_t i = 0; i < pixels.size(); ++i)
        for (int k = 0; k < 3; ++k) bad += codes[3 * i + static_cast<std::size_t>(k)] != exact_code(pixels[i][k]);
    CHECK(bad == 0);
    CHECK(codes[0] == 0);
    CHECK(codes[2] == 255);
    CHECK(codes[3] == 255);
}
