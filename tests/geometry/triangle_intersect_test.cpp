#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>

#include <catch2/catch.hpp>

#include "test_meshes.hpp"

#include <optional>

using namespace rtlab;

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();

std::optional<TriangleHit> hit_with(TriangleTest test, const Ray& ray, const Point3& a, const Point3& b,
                                    const Point3& c) {
    switch (test) {
        case TriangleTest::watertight:
            return intersect_watertight(WatertightRay(ray), ray.tmin, ray.tmax, a, b, c);
        case TriangleTest::moller:
            return intersect_moller(ray, ray.tmin, ray.tmax, a, b, c);
        case TriangleTest::plane:
            return intersect_plane(ray, ray.tmin, ray.tmax, PlaneTriangle(a, b, c));
    }
    return std::nullopt;
}

const TriangleTest kAllTests[] = {TriangleTest::watertight, TriangleTest::moller, TriangleTest::plane};

bool hits_any(TriangleTest test, const TriangleMesh& m, const Ray& ray) {
    for (std::size_t i = 0; i < m.triangle_count(); ++i)
        if (hit_with(test, ray, m.corner(i, 0), m.corner(i, 1), m.corner(i, 2))) return true;
    return false;
}

// Rays from outside aimed exactly at points of shared edges and at shared vertices of a closed icosphere,
// from directions that enter the solid there (within 60 degrees of the inward normal). Returns how many
// missed every triangle: such a ray has slipped through a crack between triangles.
int count_leaks(TriangleTest test, const TriangleMesh& m, int rays_per_target, int& total, float tmax = kInf) {
    Rng rng(2024);
    int leaks = 0;
    total = 0;
    auto aim = [&](const Point3& target) {
        const Vec3 outward = glm::normalize(target);
        for (int k = 0; k < rays_per_target; ++k) {
            Vec3 d;
            do {
                d = Vec3(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1);
            } while (glm::length(d) > 1.0f || glm::length(d) < 0.1f || glm::dot(glm::normalize(d), outward) < 0.5f);
            const Point3 origin = target + 3.0f * glm::normalize(d);
            ++total;
            if (!hits_any(test, m, Ray{origin, target - origin, 0.0f, tmax})) ++leaks;
        }
    };
    for (const auto& p : m.positions) aim(p);    // every vertex is shared by 5 or 6 triangles
    for (const auto& [a, b, c] : m.triangles) {  // points along every edge (each edge is seen twice)
        for (float s : {0.5f, 0.25f, 1.0f / 3.0f}) aim(m.positions[a] + s * (m.positions[b] - m.positions[a]));
    }
    return leaks;
}

// The same on the grid box, whose vertices and edge points are exact in float: rays are aimed at every
// vertex and at the midpoint and quarter point of every triangle edge, entering the box there (moving
// inward across every face plane the target lies on).
int count_box_leaks(TriangleTest test, const TriangleMesh& m, float n, int rays_per_target, int& total,
                    float tmax = kInf) {
    Rng rng(77);
    int leaks = 0;
    total = 0;
    auto aim = [&](const Point3& target) {
        for (int k = 0; k < rays_per_target; ++k) {
            Vec3 d;
            bool ok = false;
            while (!ok) {
                d = glm::normalize(Vec3(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1) +
                                   Vec3(1e-3f));
                ok = true;
                for (int a = 0; a < 3; ++a) {
                    if (target[a] == 0.0f && !(d[a] < -0.3f)) ok = false;
                    if (target[a] == n && !(d[a] > 0.3f)) ok = false;
                }
            }
            const Point3 origin = target + 3.0f * d;
            ++total;
            if (!hits_any(test, m, Ray{origin, target - origin, 0.0f, tmax})) ++leaks;
        }
    };
    for (const auto& p : m.positions) aim(p);
    for (const auto& [a, b, c] : m.triangles)
        for (float s : {0.5f, 0.25f}) {
            aim(m.positions[a] + s * (m.positions[b] - m.positions[a]));
            aim(m.positions[b] + s * (m.positions[c] - m.positions[b]));
            aim(m.positions[c] + s * (m.positions[a] - m.positions[c]));
        }
    return leaks;
}
}  // namespace

TEST_CASE("watertight test never leaks on the exact grid box", "[triangle]") {
    const TriangleMesh box = test::grid_box(4);
    int total = 0;
    const int leaks = count_box_leaks(TriangleTest::watertight, box, 4.0f, 20, total);
    INFO("watertight: " << leaks << " leaks of " << total << " rays");
    CHECK(total > 20000);
    CHECK(leaks == 0);
    for (TriangleTest t : {TriangleTest::moller, TriangleTest::plane}) {
        const int l = count_box_leaks(t, box, 4.0f, 20, total);
        WARN(to_string(t) << " on the grid box: " << l << " leaks of " << total << " rays (" << 100.0 * l / total
                          << "%)");
        CHECK(l < total / 10);
    }
}

TEST_CASE("watertight test never leaks at shared edges and vertices of a closed mesh", "[triangle]") {
    const TriangleMesh sphere = test::icosphere(2);
    int total = 0;
    const int leaks = count_leaks(TriangleTest::watertight, sphere, 10, total);
    INFO("watertight: " << leaks << " leaks of " << total << " rays");
    CHECK(total > 10000);
    CHECK(leaks == 0);
}

TEST_CASE("leak rates of the Moller-Trumbore and plane tests are measured", "[triangle]") {
    const TriangleMesh sphere = test::icosphere(2);
    for (TriangleTest t : {TriangleTest::moller, TriangleTest::plane}) {
        int total = 0;
        const int leaks = count_leaks(t, sphere, 10, total);
        // Not a pass/fail criterion for these two methods: the figure is reported, as the issue asks.
        WARN(to_string(t) << ": " << leaks << " leaks of " << total << " rays (" << 100.0 * leaks / total << "%)");
        CHECK(leaks < total / 10);  // a broken test would leak everywhere
    }
}

// An unbounded ray that slips through a crack of a closed mesh still hits its far side, so the leak counts
// above cannot see every leak. Rays that end just past their target (t = 1 at the target, tmax = 1.001,
// while the far side is at least 0.6 further on the sphere and a whole cell on the box) must be stopped at
// the target itself.
TEST_CASE("bounded rays ending just past shared edges and vertices: leaks per method", "[triangle]") {
    constexpr float kTmax = 1.001f;
    const TriangleMesh sphere = test::icosphere(2);
    const TriangleMesh box = test::grid_box(4);
    int total = 0;
    for (TriangleTest t : kAllTests) {
        const int sphere_leaks = count_leaks(t, sphere, 10, total, kTmax);
        const int sphere_rays = total;
        const int box_leaks = count_box_leaks(t, box, 4.0f, 20, total, kTmax);
        const int box_rays = total;
        const int leaks = sphere_leaks + box_leaks, rays = sphere_rays + box_rays;
        WARN(to_string(t) << " with bounded rays: " << leaks << " leaks of " << rays << " (icosphere " << sphere_leaks
                          << " of " << sphere_rays << ", grid box " << box_leaks << " of " << box_rays << ")");
        CHECK(rays > 30000);
        if (t == TriangleTest::watertight) {
            CHECK(leaks == 0);
        } else {
            // Measured (g++ 12, -O2, no FMA contraction): moller 2,264 (icosphere 1,159, grid box 1,105),
            // plane 1,583 (icosphere 1,583, grid box 0). Not a pass/fail criterion for these two methods,
            // which are not watertight by design; the bound catches a change that makes them much worse, and
            // a count near zero would mean the rays no longer reach the cracks.
            const int measured = t == TriangleTest::moller ? 2264 : 1583;
            CHECK(leaks > measured / 2);
            CHECK(leaks < measured * 3 / 2);
        }
    }
}

TEST_CASE("hits report t and barycentrics consistent with the hit point", "[triangle]") {
    const Point3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    const Ray ray{{0.5f, 0.25f, 3.0f}, {0, 0, -1}};
    for (TriangleTest t : kAllTests) {
        const auto h = hit_with(t, ray, a, b, c);
        REQUIRE(h);
        CHECK(h->t == Approx(3.0f));
        CHECK(h->u == Approx(0.25f));   // weight of b
        CHECK(h->v == Approx(0.125f));  // weight of c
        // Both windings are hit (no back-face culling).
        REQUIRE(hit_with(t, ray, a, c, b));
    }
}

TEST_CASE("the hit interval is open and respects tmin and tmax", "[triangle]") {
    const Point3 a(-1, -1, 0), b(1, -1, 0), c(0, 1, 0);
    for (TriangleTest t : kAllTests) {
        CHECK_FALSE(hit_with(t, Ray{{0, 0, 1}, {0, 0, -1}, 0.0f, 1.0f}, a, b, c));  // t = tmax exactly
        CHECK(hit_with(t, Ray{{0, 0, 1}, {0, 0, -1}, 0.0f, 1.0001f}, a, b, c));
        CHECK_FALSE(hit_with(t, Ray{{0, 0, 1}, {0, 0, -1}, 1.0f, kInf}, a, b, c));  // t = tmin exactly
        CHECK_FALSE(hit_with(t, Ray{{0, 0, 0}, {0, 0, -1}, 0.0f, kInf}, a, b, c));  // starts on the surface
        CHECK_FALSE(hit_with(t, Ray{{0, 0, 1}, {0, 0, 1}, 0.0f, kInf}, a, b, c));   // pointing away
        CHECK_FALSE(hit_with(t, Ray{{0, 0, 1}, {0, 0, -1}, 0.5f, 0.5f}, a, b, c));  // tmin = tmax
    }
}

TEST_CASE("degenerate triangles are never hit and never produce NaN", "[triangle]") {
    const Point3 p(0, 0, 0), q(1, 1, 0), r(2, 2, 0);
    const Ray rays[] = {Ray{{1, 1, 1}, {0, 0, -1}}, Ray{{0.5f, 0.5f, 1}, {0, 0, -1}}, Ray{{-1, -1, 0}, {1, 1, 0}},
                        Ray{{0, 0, 1}, {0, 0, -1}}};
    for (TriangleTest t : kAllTests) {
        for (const Ray& ray : rays) {
            CHECK_FALSE(hit_with(t, ray, p, q, r));  // collinear
            CHECK_FALSE(hit_with(t, ray, p, p, q));  // repeated corner
            CHECK_FALSE(hit_with(t, ray, p, p, p));  // a point
        }
    }
}

TEST_CASE("rays in the triangle's plane and parallel to it miss", "[triangle]") {
    const Point3 a(-1, -1, 0), b(1, -1, 0), c(0, 1, 0);
    for (TriangleTest t : kAllTests) {
        CHECK_FALSE(hit_with(t, Ray{{-5, 0, 0}, {1, 0, 0}}, a, b, c));      // in the plane, through the triangle
        CHECK_FALSE(hit_with(t, Ray{{-5, 0, 1e-3f}, {1, 0, 0}}, a, b, c));  // parallel above it
    }
}

TEST_CASE("grazing rays and huge and tiny scales and large offsets", "[triangle]") {
    for (float scale : {1e-4f, 1.0f, 1e5f}) {
        for (float offset : {0.0f, 1e6f}) {
            const Vec3 o(offset, -offset, offset);
            const Point3 a = o + scale * Vec3(-1, -1, 0), b = o + scale * Vec3(1, -1, 0), c = o + scale * Vec3(0, 1, 0);
            // A grazing ray at 89.9 degrees from the normal, through the centroid region.
            const Vec3 dir = glm::normalize(Vec3(1.0f, 0.0f, -std::tan(0.1f * kPi / 180.0f)));
            const Point3 target = o + scale * Vec3(0, -0.3f, 0);
            for (TriangleTest t : kAllTests) {
                INFO("scale " << scale << " offset " << offset << " test " << to_string(t));
                const auto head_on = hit_with(t, Ray{target + Vec3(0, 0, 2 * scale), {0, 0, -1}}, a, b, c);
                if (offset == 0.0f || scale >= 1.0f) {  // 1e-4 triangles at 1e6 are below float resolution
                    REQUIRE(head_on);
                    CHECK(head_on->t == Approx(2 * scale).epsilon(1e-3));
                }
                const auto graze = hit_with(t, Ray{target - 0.5f * scale * dir, dir}, a, b, c);
                if (offset == 0.0f) {
                    REQUIRE(graze);
                    CHECK(graze->t == Approx(0.5f * scale).epsilon(1e-2));
                }
            }
        }
    }
}

TEST_CASE("NaN, infinite and zero-direction rays miss", "[triangle]") {
    const Point3 a(-1, -1, 0), b(1, -1, 0), c(0, 1, 0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (TriangleTest t : kAllTests) {
        CHECK_FALSE(hit_with(t, Ray{{0, 0, 1}, {nan, 0, -1}}, a, b, c));
        CHECK_FALSE(hit_with(t, Ray{{nan, 0, 1}, {0, 0, -1}}, a, b, c));
        CHECK_FALSE(hit_with(t, Ray{{0, 0, 1}, {0, 0, 0}}, a, b, c));
        CHECK_FALSE(hit_with(t, Ray{{0, 0, 1}, {0, 0, -1}, nan, kInf}, a, b, c));
    }
}

TEST_CASE("triangle test names", "[triangle]") {
    CHECK(parse_triangle_test("plane") == TriangleTest::plane);
    CHECK(to_string(TriangleTest::moller) == "moller");
    CHECK_THROWS_WITH(parse_triangle_test("woop"), Catch::Matchers::Contains("watertight, moller, plane"));
}
