#include <rtlab/core/aabb.hpp>
#include <rtlab/core/box_ray.hpp>

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

TEST_CASE("slab test: rays in every face plane with +0 and -0 components", "[aabb]") {
    // For each face (axis a, side lo or hi) and each of the two other axes b as the direction: the origin
    // lies in the face plane, 5 before the box along b, and the direction's a component is +0 or -0.
    // The ray runs in the face through the box: [4, 6] exactly, for every sign of every zero.
    int checked = 0;
    for (int a = 0; a < 3; ++a)
        for (float side : {-1.0f, 1.0f})
            for (int b = 0; b < 3; ++b) {
                if (b == a) continue;
                for (float along : {-1.0f, 1.0f})
                    for (float za : {0.0f, -0.0f})
                        for (float zc : {0.0f, -0.0f}) {
                            const int c = 3 - a - b;
                            Point3 o(0.0f);
                            Vec3 d(0.0f);
                            o[a] = side;
                            o[b] = -5.0f * along;
                            o[c] = 0.5f;
                            d[a] = za;
                            d[b] = along;
                            d[c] = zc;
                            const auto hit = unit_box.intersect(Ray{o, d});
                            INFO("face axis " << a << " side " << side << " along " << b << " " << along);
                            REQUIRE(hit);
                            CHECK(hit->min == 4.0f);
                            CHECK(hit->max >= 6.0f);
                            CHECK(hit->max <= 6.0f * (1.0f + 2.0f * gamma_bound(3)));
                            // Just outside the face plane: a miss whatever the zero's sign.
                            o[a] = std::nextafter(side, 2.0f * side);
                            CHECK_FALSE(unit_box.intersect(Ray{o, d}));
                            ++checked;
                        }
            }
    CHECK(checked == 96);
}

TEST_CASE("slab test: edges flat boxes and zero directions", "[aabb]") {
    for (float z : {0.0f, -0.0f}) {
        // Along an edge (y = 1, z = -1) with both other components zero.
        const auto edge = unit_box.intersect(Ray{{-3, 1, -1}, {2, z, z}});
        REQUIRE(edge);
        CHECK(edge->min == 1.0f);
        // A flat box (zero thickness in y) and a ray in its plane: a hit; just beside it: a miss.
        const AABB flat{{-1, 2, -1}, {1, 2, 1}};
        const auto in_plane = flat.intersect(Ray{{0, 2, -4}, {z, z, 1}});
        REQUIRE(in_plane);
        CHECK(in_plane->min == 3.0f);
        CHECK_FALSE(flat.intersect(Ray{{0, std::nextafter(2.0f, 3.0f), -4}, {z, z, 1}}));
        // Crossing the flat box: entry and exit at the same t.
        const auto cross = flat.intersect(Ray{{0.5f, 0, 0.5f}, {z, 1, z}});
        REQUIRE(cross);
        CHECK(cross->min == 2.0f);
        CHECK(cross->max >= 2.0f);
        // A zero direction: inside is [tmin, tmax], outside is a miss even with tmax infinite.
        const auto still = unit_box.intersect(Ray{{0.5f, 0.5f, 0.5f}, {z, z, z}, 0.0f, 10.0f});
        REQUIRE(still);
        CHECK(still->min == 0.0f);
        CHECK(still->max == 10.0f);
        // Outside on either side, also for the whole line (tmin = -inf, as the box shape asks) and for a
        // ray moving along another axis: the zero axis gives an entry at +inf or an exit at -inf.
        for (float x : {3.0f, -3.0f}) {
            CHECK_FALSE(unit_box.intersect(Ray{{x, 0, 0}, {z, z, z}}));
            CHECK_FALSE(unit_box.intersect(Ray{{x, 0, 0}, {z, z, z}, -kInf, kInf}));
            CHECK_FALSE(unit_box.intersect(Ray{{x, 0, -5}, {z, z, 1}, -kInf, kInf}));
        }
        const auto line = unit_box.intersect(Ray{{0.5f, 0, -5}, {z, z, 1}, -kInf, kInf});
        REQUIRE(line);
        CHECK(line->min == 4.0f);
    }
}

TEST_CASE("AABB intersect and BoxRay clip agree on random rays with zero components and face origins", "[aabb]") {
    std::uint32_t state = 3;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) * 0x1p-24f;
    };
    // Coordinates drawn from the box planes, just beside them, and the inside, so that origins sit on faces.
    const float picks[] = {-1.0f, 1.0f, std::nextafter(1.0f, 2.0f), std::nextafter(-1.0f, -2.0f), 0.0f, 0.25f, -3.0f};
    int hits = 0, disagree = 0;
    for (int i = 0; i < 200000; ++i) {
        Point3 o;
        Vec3 d;
        for (int a = 0; a < 3; ++a) {
            o[a] = picks[static_cast<int>(next() * 7.0f)];
            const float r = next();
            d[a] = r < 0.2f ? 0.0f : r < 0.4f ? -0.0f : (next() - 0.5f) * 4.0f;
        }
        const float tmin = next() < 0.3f ? -kInf : 0.0f;
        const float tmax = next() < 0.5f ? kInf : next() * 8.0f;
        const Ray ray{o, d, tmin, tmax};
        const auto hit = unit_box.intersect(ray);
        float t0 = 0.0f, t1 = 0.0f;
        const bool clip = BoxRay(ray).clip(unit_box, tmax, t0, t1) && t0 <= tmax && t0 < kInf && t1 > -kInf;
        hits += hit ? 1 : 0;
        if (hit.has_value() != clip || (hit && (hit->min != t0 || hit->max != std::min(t1, tmax)))) ++disagree;
        // A hit's range is inside the ray's.
        if (hit && !(hit->min >= tmin && hit->max <= tmax && hit->min <= hit->max)) ++disagree;
    }
    CHECK(disagree == 0);
    CHECK(hits > 20000);
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
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, 5}, {0, 0, 1}}));            // box behind
    CHECK_FALSE(unit_box.intersect(Ray{{0, 0, -5}, {0, 0, 1}, 0, 3.9f}));  // stops short
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
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) * 0x1p-24f;
    };
    int misses = 0;
    for (int i = 0; i < 20000; ++i) {
        const AABB box =
            AABB::from_points({next() * 100, next() * 100, next() * 100}, {next() * 100, next() * 100, next() * 100});
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
