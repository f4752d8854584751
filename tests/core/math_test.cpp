#include <rtlab/core/math.hpp>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

using namespace rtlab;

namespace {

bool same_bits(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
    return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

}  // namespace

TEST_CASE("next_float_up and next_float_down match std::nextafter on the edge cases", "[core][math]") {
    using L = std::numeric_limits<float>;
    const std::vector<float> values = {0.0f,
                                       -0.0f,
                                       L::denorm_min(),
                                       -L::denorm_min(),
                                       L::min(),
                                       -L::min(),
                                       1.0f,
                                       -1.0f,
                                       0.1f,
                                       -3.5e7f,
                                       L::max(),
                                       -L::max(),
                                       L::infinity(),
                                       -L::infinity(),
                                       L::quiet_NaN(),
                                       L::epsilon(),
                                       1.0f - L::epsilon()};
    for (float x : values) {
        INFO("x = " << x);
        CHECK(same_bits(next_float_up(x), std::nextafter(x, L::infinity())));
        CHECK(same_bits(next_float_down(x), std::nextafter(x, -L::infinity())));
    }
}

TEST_CASE("next_float_up and next_float_down match std::nextafter across the float range", "[core][math]") {
    // Every 4099th bit pattern, both signs: subnormals, normals, the infinities' neighbours and NaNs.
    std::uint64_t checked = 0;
    for (std::uint64_t bits = 0; bits <= 0xFFFFFFFFull; bits += 4099) {
        const float x = std::bit_cast<float>(static_cast<std::uint32_t>(bits));
        if (!same_bits(next_float_up(x), std::nextafter(x, std::numeric_limits<float>::infinity())) ||
            !same_bits(next_float_down(x), std::nextafter(x, -std::numeric_limits<float>::infinity()))) {
            FAIL("differs at bits " << bits);
        }
        ++checked;
    }
    CHECK(checked > 1000000);
}
