#include <rtlab/accel/hit_agreement.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace rtlab;

namespace {
MeshHit at(float t, std::uint32_t primitive = 3) { return MeshHit{t, primitive, 0.25f, 0.25f}; }
constexpr float kMax = std::numeric_limits<float>::max();
constexpr float kInf = std::numeric_limits<float>::infinity();
}  // namespace

TEST_CASE("same_hit: hit against miss differs and two misses agree whatever their records", "[hit_agreement]") {
    CHECK_FALSE(same_hit(true, at(1.0f), false, MeshHit{}));
    CHECK_FALSE(same_hit(false, MeshHit{}, true, at(1.0f)));
    CHECK(same_hit(false, MeshHit{}, false, MeshHit{}));
    // A miss's record is left over from whatever the tracer wrote: it is not looked at.
    CHECK(same_hit(false, at(1.0f, 0), false, at(7.0f, 9)));
    CHECK(same_hit(false, at(std::nanf("")), false, MeshHit{}));
}

TEST_CASE("same_hit: t = 0 matches only 0 of either sign", "[hit_agreement]") {
    CHECK(same_hit(true, at(0.0f), true, at(0.0f)));
    CHECK(same_hit(true, at(0.0f), true, at(-0.0f)));
    CHECK_FALSE(same_hit(true, at(0.0f), true, at(1e-30f)));
    CHECK_FALSE(same_hit(true, at(std::numeric_limits<float>::denorm_min()), true, at(0.0f)));
    // Subnormal t: relative as everywhere else.
    const float tiny = std::numeric_limits<float>::denorm_min();
    CHECK(same_hit(true, at(1e6f * tiny), true, at(1e6f * tiny + tiny)));
    CHECK_FALSE(same_hit(true, at(tiny), true, at(2 * tiny)));
}

TEST_CASE("same_hit: huge and infinite t", "[hit_agreement]") {
    CHECK(same_hit(true, at(kMax), true, at(kMax)));
    CHECK(same_hit(true, at(kMax), true, at(kMax * (1.0f - 5e-5f))));
    CHECK_FALSE(same_hit(true, at(kMax), true, at(kMax * (1.0f - 2e-4f))));
    CHECK_FALSE(same_hit(true, at(kMax), true, at(-kMax)));  // a float difference would overflow
    CHECK(same_hit(true, at(kInf), true, at(kInf)));
    CHECK_FALSE(same_hit(true, at(kInf), true, at(kMax)));  // inf - max <= tol * inf would accept it
    CHECK_FALSE(same_hit(true, at(kMax), true, at(kInf)));
    CHECK_FALSE(same_hit(true, at(kInf), true, at(-kInf)));
    CHECK_FALSE(same_hit(true, at(std::nanf("")), true, at(std::nanf(""))));
    CHECK_FALSE(same_hit(true, at(1.0f), true, at(std::nanf(""))));
}

TEST_CASE("same_hit: a different primitive only at the same t", "[hit_agreement]") {
    CHECK(same_hit(true, at(2.0f, 4), true, at(2.0f, 5)));                        // the other side of a shared edge
    CHECK(same_hit(true, at(2.0f, 4), true, at(std::nextafter(2.0f, 3.0f), 5)));  // one ulp apart
    CHECK_FALSE(same_hit(true, at(2.0f, 4), true, at(2.001f, 5)));                // a surface behind
    CHECK_FALSE(same_hit(true, at(2.0f, 4), true, at(2.001f, 4)));                // the same triangle, not the same t
}

TEST_CASE("same_hit: the tolerance is relative at every scale", "[hit_agreement]") {
    // The verdict is the same whether the mesh is measured in metres or in light years: at each scale,
    // 4e-5 relative apart is the same hit and 3e-4 relative apart is not.
    int scales = 0, same_close = 0, same_far = 0;
    for (int e = -120; e <= 120; e += 8) {
        const float t = std::ldexp(1.5f, e);
        ++scales;
        same_close += same_hit(true, at(t), true, at(t * (1.0f + 4e-5f)));
        same_far += same_hit(true, at(t), true, at(t * (1.0f + 3e-4f)));
        CHECK(same_hit(true, at(-t), true, at(-t * (1.0f + 4e-5f))));  // tmin < 0 allows negative t
    }
    CHECK(scales == 31);
    CHECK(same_close == scales);
    CHECK(same_far == 0);
    // No absolute floor: with the tests' former floor (1e-4 absolute below t = 1) each pair was one hit,
    // which on a mesh a few 1e-4 across are two different surfaces.
    CHECK_FALSE(same_hit(true, at(1e-4f), true, at(1.9e-4f)));
    CHECK_FALSE(same_hit(true, at(0.5f), true, at(0.50009f)));
}
