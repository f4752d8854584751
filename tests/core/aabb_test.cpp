#include <rtlab/core/aabb.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace rtlab;

namespace {
const AABB unit_box{{-1, -1, -1}, {1, 1, 1}};
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
}  // namespace

TEST_CASE("slab test: axis-parallel rays with +0 and -0 components", "[aabb]") {
    for (float zero : {0.0f, -0.0f}) {
        // Travels along +x at y = z = 0 with zero (or negative-zero) y and z.
        const auto hit = unit_box.intersect(Ray{{-5, 0, 0}, {1, zero, zero}});
        REQUIRE(hit);
        CHECK(hit->min == Approx(4.0f));
        CHECK(hit->max == Approx(6.0f));
        // Parallel to the slab but outside it: a miss, not a NaN-driven hit.
        CHECK_FALSE(unit_box.intersect(Ray{{-5, 2, 0}, {1, zero, zero}}));
        CHECK_FALSE(unit_box.intersect(Ray{{-5, 0, -1.5f}, {1, zero, zero}}));
    }
}

TEST_CASE("slab test: rays lying exactly in a face plane", "[aabb]") {
    // Origin on the y = 1 plane, direction with y = 0: 0 / 0 would be NaN in a naive test.
    for (float zero : {0.0f, -0.0f}) {
        const auto hit = unit_box.intersect(Ray{{-5, 1, 0}, {1, zero, 0}});
        REQUIRE(hit);
        CHECK(hit->min == Approx(4.0f));
        const auto hit2 = unit_box.intersect(Ray{{-5, -1, 1}, {1, zero, zero}});
        REQUIRE(hit2);
    }
}

TEST_CASE("slab test: denormal direction components do not produce NaN", "[aabb]") {
    const float tiny = std::numeric_limits<float>::denorm_min();
    // The origin lies on the x = -1 plane and the x direction is denormal: (lo - o) * (1 / d) = 0 * kInf.
    const auto hit = unit_box.intersect(Ray{{-1, 0, -5}, {tiny, 0, 1}});
    REQUIRE(hit);
    CHECK(hit->min == Approx(4.0f));
    CHECK(std::isfinite(hit->max));
    // Far off in x with a denormal x direction: never gets there.
    CHECK_FALSE(unit_box.intersect(Ray{{-3, 0, -5}, {tiny, 0, 1}}));
    CHECK_FALSE(unit_box.intersect(Ray{{-3, 0, -5}, {-tiny, 0, 1}}));
}

TEST_CASE("slab test: origin inside and on the boundary", "[aabb]") {
    const auto inside = unit_box.intersect(Ray{{0, 0, 0}, {0.3f, -0.5f, 0.8f}});
    REQUIRE(inside);
    CHECK(inside->min == 0.0f);
    CHECK(inside->max > 0.0f);
    const auto on_face = unit_box.intersect(Ray{{1, 0, 0}, {1, 0, 0}});  // leaving through the face
    REQUIRE(on_face);
    CHECK(on_face->min == 0.0f);
    CHECK(on_face->max == Approx(0.0f).margin(1e-6));
    const auto corner = unit_box.intersect(Ray{{-2, -2, -2}, {1, 1, 1}});  // through two corners
    REQUIRE(corner);
    CHECK(corner->min == Approx(1.0f));
    CHECK(corner->max == Approx(3.0f));
    const auto graze = unit_box.intersect(Ray{{-2, 1, 1}, {1, 0, 0}});  // along an edge
    REQUIRE(graze);
}

TEST_CASE("slab test: tmin/tmax clipping and behind-the-origin boxes", "[aabb]") {
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, 5}, {0, 0, 1}}));         // box behind
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, -5}, {0, 0, 1}, 0, 3.9f})); // stops short
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, -5}, {0, 0, 1}, 6.1f, kInf}));
    const auto exact = unit_box.intersect(Ray{{0, 0, -5}, {0, 0, 1}, 5.0f, 5.0f});  // tmin = tmax inside
    REQUIRE(exact);
    CHECK(exact->min == 5.0f);
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, -5}, {0, 0, 1}, 5.0f, 4.0f}));  // tmin > tmax
}

TEST_CASE("slab test: NaN and infinite rays are misses", "[aabb]") {
    CHECK_FALSE(unit_box.intersect(Ray{{kNaN, 0, 0}, {1, 0, 0}}));
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, 0}, {kNaN, 0, 1}}));
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, 0}, {0, 0, 1}, kNaN, kInf}));
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, 0}, {0, 0, 1}, 0, kNaN}));
    CHECK_FALSE(unit_box.intersect(Ray{{-kInf, 0, 0}, {1, 0, 0}}));
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, -5}, {0, kInf, 1}}));
    CHECK_FALSE(AABB{}.intersect(Ray{{0, 0, 0}, {1, 0, 0}}));  // empty box
}

TEST_CASE("slab test: huge and tiny boxes", "[aabb]") {
    const AABB huge{{1e6f, 1e6f, 1e6f}, {1e6f + 1, 1e6f + 1, 1e6f + 1}};
    const Point3 origin{0, 0, 0};
    const Vec3 dir = glm::normalize(huge.center() - origin);
    REQUIRE(huge.intersect(Ray{origin, dir}));
    const AABB tiny{{-1e-30f, -1e-30f, -1e-30f}, {1e-30f, 1e-30f, 1e-30f}};
    REQUIRE(tiny.intersect(Ray{{0, 0, -1}, {0, 0, 1}}));
    CHECK_FALSE(tiny.intersect(Ray{{1e-29f, 0, -1}, {0, 0, 1}}));
}

TEST_CASE("slab test never misses a ray through the box centre (random)", "[aabb]") {
    // Rays from far away aimed at a point inside: rounding must never turn them into misses.
    std::uint32_t state = 7;
    auto next = [&] { state = state * 1664525u + 1013904223u; return static_cast<float>(state >> 8) * 0x1p-24f; };
    int misses = 0;
    for (int i = 0; i < 20000; ++i) {
        const AABB box = AABB::from_points({next() * 100, next() * 100, next() * 100}, {next() * 100, next() * 100, next() * 100});
        const Point3 target = box.lo + Vec3(next(), next(), next()) * box.extent();
        const Point3 origin = Vec3(next() - 0.5f, next() - 0.5f, next() - 0.5f) * 1e4f;
        if (!box.intersect(Ray{origin, target - origin})) ++misses;
    }
    CHECK(misses == 0);
}

TEST_CASE("AABB helpers", "[aabb]") {
    AABB b;
    CHECK(b.is_empty());
    CHECK(b.surface_area() == 0.0f);
    b.expand(Point3{0, 0, 0});
    b.expand(Point3{1, 2, 3});
    CHECK_FALSE(b.is_empty());
    CHECK(b.surface_area() == Approx(2 * (2 + 6 + 3)));
    CHECK(b.longest_axis() == 2);
    CHECK(b.contains({0.5f, 1, 1}));
    CHECK_FALSE(b.contains({0.5f, 1, 4}));
}
