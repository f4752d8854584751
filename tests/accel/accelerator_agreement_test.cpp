#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/accel/ray_io.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>

#include <catch2/catch.hpp>

#include <span>

#include "agreement.hpp"
#include "sample_scale.hpp"
#include "test_meshes.hpp"

using namespace rtlab;

namespace {

// Rays along the axes in both directions, with +0 and -0 in the other components, from a grid of
// origins that includes vertex and edge coordinates of the test meshes.
std::vector<Ray> axis_rays(const AABB& b, int n) {
    std::vector<Ray> rays;
    const Vec3 e = b.extent();
    for (int axis = 0; axis < 3; ++axis) {
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        for (float sign : {1.0f, -1.0f})
            for (float zero : {0.0f, -0.0f})
                for (int i = 0; i <= n; ++i)
                    for (int j = 0; j <= n; ++j) {
                        Point3 o;
                        o[axis] = sign > 0 ? b.lo[axis] - 1.0f : b.hi[axis] + 1.0f;
                        o[a1] = b.lo[a1] + e[a1] * static_cast<float>(i) / static_cast<float>(n);
                        o[a2] = b.lo[a2] + e[a2] * static_cast<float>(j) / static_cast<float>(n);
                        Vec3 d(zero);
                        d[axis] = sign;
                        rays.push_back(Ray{o, d});
                    }
    }
    return rays;
}

std::vector<Ray> standard_rays(const TriangleMesh& mesh, std::size_t random_count, int primary_n, int axis_n) {
    const AABB b = mesh.bounds();
    std::vector<Ray> rays = random_rays(b, random_count, 7);
    for (const Ray& r : primary_rays(b, primary_n)) rays.push_back(r);
    for (const Ray& r : axis_rays(b, axis_n)) rays.push_back(r);
    // Rays starting inside the box in random directions, some with limited tmax.
    Rng rng(5);
    for (int i = 0; i < 300; ++i) {
        const Point3 o = b.lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * b.extent();
        const Vec3 d(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f);
        rays.push_back(Ray{o, d, 0.0f, i % 3 == 0 ? 0.3f : kInfinity});
    }
    return rays;
}

// The methods to check with one leaf width: every method at the first width, and the kd-trees over
// triangles (whose leaves are packets of that width) at the others.
std::vector<std::string> methods_at_width(int width) {
    return width == kd_leaf_widths().front() ? accelerator_methods() : kd_tree_methods();
}

// Embree is checked only on ordinary meshes: on the adversarial ones (rays starting on a plane of 1000
// coincident quads) its own arithmetic legitimately gives a tiny positive t where rtlab's tests give 0.

constexpr TriangleTest kAllTests[] = {TriangleTest::watertight, TriangleTest::moller, TriangleTest::plane};

void check_all_methods(const std::string& label, const TriangleMesh& mesh, const std::vector<Ray>& rays,
                       bool include_naive, bool include_embree = true,
                       std::span<const TriangleTest> tests = kAllTests) {
    for (TriangleTest test : tests) {
        BuildOptions options;
        options.triangle_test = test;
        const auto reference = test::answers(*make_accelerator("brute", mesh, options), rays);
        for (int width : kd_leaf_widths()) {
            options.leaf_width = width;
            for (const std::string& method : methods_at_width(width)) {
                if (method == "brute" || (method == "kd-sah-naive" && !include_naive)) continue;
                if (method == "embree" && (test != TriangleTest::watertight || !include_embree)) continue;
                const auto accel = make_accelerator(method, mesh, options);
                const test::Agreement a = test::compare(*accel, reference, rays);
                INFO(label << ", " << method << ", " << to_string(test) << ", leaf width " << width << ": "
                           << a.mismatches << " closest-hit and " << a.anyhit_mismatches << " any-hit mismatches of "
                           << a.rays << " rays (" << a.hits << " hits)");
                // Embree's own watertight test may pick the other of two triangles sharing an edge at equal
                // t: same_hit accepts that; it may not disagree on hit or miss beyond rounding at silhouettes.
                if (method == "embree") {
                    CHECK(a.mismatches <= a.rays / 1000);
                } else {
                    CHECK(a.mismatches == 0);
                    CHECK(a.anyhit_mismatches == 0);
                }
            }
        }
    }
}

}  // namespace

TEST_CASE("every method agrees with brute force on random triangle soup", "[accel]") {
    TriangleMesh soup = test::random_soup(1500, 1, 1.5f);
    // Degenerate triangles mixed in: a repeated corner and a collinear one.
    soup.positions.insert(soup.positions.end(), {Point3(5, 5, 5), Point3(6, 6, 6), Point3(7, 7, 7)});
    const auto n = static_cast<std::uint32_t>(soup.positions.size());
    soup.triangles.push_back({n - 3, n - 2, n - 1});
    soup.triangles.push_back({n - 3, n - 3, n - 1});
    check_all_methods("soup", soup, standard_rays(soup, 2000, 16, 12), true);
}

TEST_CASE("every method agrees with brute force on a closed icosphere", "[accel]") {
    const TriangleMesh sphere = test::icosphere(3);
    check_all_methods("icosphere", sphere, standard_rays(sphere, 2000, 16, 16), true);
}

TEST_CASE("rays lying in the faces of the root box with +0 and -0 components", "[accel]") {
    // The root box clip takes the inverse direction, so a zero component is an infinite inverse and an
    // origin on that face plane gives 0 * inf = NaN: the clip must keep such rays (they run along the
    // box's faces and hit the edges of the perpendicular faces), for +0 and -0 alike.
    const int n = 6;
    const TriangleMesh box = test::grid_box(n);
    std::vector<Ray> rays;
    const float size = static_cast<float>(n);
    for (int face_axis = 0; face_axis < 3; ++face_axis)
        for (float face : {0.0f, size})
            for (float zero : {0.0f, -0.0f})
                for (int k = 1; k < 3; ++k) {
                    const int along = (face_axis + k) % 3, other = (face_axis + 3 - k) % 3;
                    for (float sign : {1.0f, -1.0f})
                        for (int i = 0; i <= 2 * n; ++i) {  // vertex and edge-midpoint coordinates
                            Point3 o;
                            o[face_axis] = face;
                            o[along] = sign > 0 ? -2.0f : size + 2.0f;
                            o[other] = 0.5f * static_cast<float>(i);
                            Vec3 d(0.0f);
                            d[face_axis] = zero;
                            d[along] = sign;
                            d[other] = (i % 3 == 0) ? -0.0f : 0.25f;  // along the face, straight or slanted
                            rays.push_back(Ray{o, d});
                        }
                }
    const auto reference = test::answers(*make_accelerator("brute", box), rays);
    for (const std::string& method : accelerator_methods()) {
        if (method == "brute" || method == "embree") continue;
        const auto accel = make_accelerator(method, box);
        const test::Agreement a = test::compare(*accel, reference, rays);
        INFO(method << ": " << a.mismatches << " closest-hit and " << a.anyhit_mismatches << " any-hit mismatches of "
                    << a.rays << " rays (" << a.hits << " hits)");
        CHECK(a.hits > a.rays / 2);  // the edges of the perpendicular faces are hit, watertight
        CHECK(a.mismatches == 0);
        CHECK(a.anyhit_mismatches == 0);
    }
}

TEST_CASE("1000 quads stacked at one coordinate", "[accel]") {
    const TriangleMesh quads = test::stacked_quads(1000, 1.0f);
    std::vector<Ray> rays = standard_rays(quads, 1000, 12, 10);
    // Rays lying in the plane x = 1 of every quad, and rays crossing it head-on at shared edges.
    for (int i = 0; i <= 40; ++i) {
        const float y = 0.05f * static_cast<float>(i);
        rays.push_back(Ray{{1.0f, y, -1.0f}, {0.0f, 0.0f, 1.0f}});
        rays.push_back(Ray{{1.0f, -1.0f, 0.5f}, {-0.0f, 1.0f, 0.0f}});
        rays.push_back(Ray{{0.0f, y, 0.5f}, {1.0f, 0.0f, -0.0f}});
        rays.push_back(Ray{{2.0f, y, 1.0f}, {-1.0f, 0.0f, 0.0f}});
    }
    check_all_methods("stacked quads", quads, rays, true, false);
}

// Under the sanitizers the grid has a quarter of the triangles: six builds of 100k triangles per triangle test
// and leaf width took over two minutes there, and the release run checks the full grid.
TEST_CASE("a grid of 100k coplanar triangles hit head-on and edge-on and in-plane", "[accel]") {
    const int n = test::kSanitized ? 112 : 224;
    const TriangleMesh grid = test::coplanar_grid(n, 0.5f);  // 100,352 triangles in z = 0.5 (25,088 sanitized)
    REQUIRE(grid.triangle_count() == static_cast<std::size_t>(2 * n * n));
    std::vector<Ray> rays;
    Rng rng(3);
    for (int i = 0; i < 100; ++i) {
        // Head-on at integer (vertex) and half-integer (edge) coordinates, and at random points.
        const float x = static_cast<float>(rng.uniform_u32(n)) + (i % 3 == 0   ? 0.0f
                                                                  : i % 3 == 1 ? 0.5f
                                                                               : rng.uniform());
        const float y = static_cast<float>(rng.uniform_u32(n)) + (i % 2 == 0 ? 0.0f : rng.uniform());
        rays.push_back(Ray{{x, y, 3.0f}, {0.0f, -0.0f, -1.0f}});
        rays.push_back(Ray{{x, y, -3.0f}, {-0.0f, 0.0f, 1.0f}});
        // Edge-on: in the plane of the grid, along x and along the diagonal.
        rays.push_back(Ray{{-1.0f, y, 0.5f}, {1.0f, 0.0f, 0.0f}});
        rays.push_back(Ray{{-1.0f, -1.0f, 0.5f}, {1.0f, 1.0f, -0.0f}});
        // Slanted through the plane.
        rays.push_back(Ray{{x, y, 2.0f}, {0.3f, -0.2f, -1.0f}});
    }
    for (TriangleTest test : {TriangleTest::watertight, TriangleTest::moller}) {
        BuildOptions options;
        options.triangle_test = test;
        const auto reference = test::answers(*make_accelerator("brute", grid, options), rays);
        for (int width : kd_leaf_widths()) {
            options.leaf_width = width;
            for (const char* method : {"kd-sah", "kd-sah-binned", "kd-median", "kd-midpoint", "bvh", "octree"}) {
                const auto accel = make_accelerator(method, grid, options);
                const test::Agreement a = test::compare(*accel, reference, rays);
                INFO(method << ", " << to_string(test) << ", leaf width " << width << ": " << a.mismatches
                            << " mismatches of " << a.rays);
                CHECK(a.mismatches == 0);
                CHECK(a.anyhit_mismatches == 0);
            }
        }
    }
}

TEST_CASE("rays lying in interior split planes of a cube lattice at coordinates from 1e-4 to 1e6", "[accel]") {
    // Faces of neighbouring cubes share lattice planes, where the trees split. A ray lying in such a plane
    // (its component there +0 or -0, the origin on the plane) gets a NaN plane distance there: the kd walk
    // then visits the near child first and keeps the far child over the whole interval, under nodes pushed
    // later that begin further along, so a hit found in the near child must not end the walk before the far
    // child's closer one (kd-trees missed 63-197 of 2000-3000 such rays before). Rays along the axes through
    // lattice lines and cell centres, and rays inside the face planes at a slant.
    for (float scale : {1.0f, 1e-6f, 1e4f}) {
        const Point3 offset = scale * Point3(100.0f, -50.0f, 25.0f);  // coordinates ~1e-4, ~1e2 and ~1e6
        const TriangleMesh lattice = test::cube_lattice(scale, offset);
        std::vector<Ray> rays;
        auto at = [&](int axis, float k) { return offset[axis] + scale * k; };
        for (int axis = 0; axis < 3; ++axis) {
            const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            for (float sign : {1.0f, -1.0f})
                for (float zero : {0.0f, -0.0f})
                    for (int i = 0; i <= 8; ++i)
                        for (int j = 0; j <= 8; ++j) {
                            Point3 o;
                            o[axis] = at(axis, sign > 0 ? -2.0f : 6.0f);
                            o[a1] = at(a1, 0.5f * static_cast<float>(i));
                            o[a2] = at(a2, 0.5f * static_cast<float>(j));
                            Vec3 d(zero);
                            d[axis] = sign;
                            rays.push_back(Ray{o, d});
                            // In the plane x_a2 = lattice value, slanted along a1.
                            if (j % 2 == 0) {
                                d[a1] = (i % 2 == 0 ? 0.375f : -0.625f) * sign;
                                rays.push_back(Ray{o, d});
                            }
                        }
        }
        check_all_methods("cube lattice at scale " + std::to_string(scale), lattice, rays, true, false);
    }
}

TEST_CASE("every method agrees with brute force on a small sphere far from the origin hit from far away", "[accel]") {
    // A sphere 1e4 to 3e4 from the origin, hit by rays from the origin itself (3.7e4 away), aimed exactly at its
    // vertices and edge midpoints, where the watertight test is at its rounding limits, and by rays starting on
    // its vertices, going in and out: every margin that is relative to coordinates (the walk's, a slab test's)
    // meets coordinates far larger than the sphere.
    for (float radius : {1.0f, 100.0f}) {
        const TriangleMesh sphere = test::icosphere(3, radius, Point3(1e4f, -2e4f, 3e4f));
        std::vector<Ray> rays = standard_rays(sphere, 1000, 8, 8);
        const Point3 centre(1e4f, -2e4f, 3e4f);
        for (const auto& tri : sphere.triangles) {
            const Point3 a = sphere.positions[tri[0]], b = sphere.positions[tri[1]];
            for (const Point3& target : {a, 0.5f * (a + b)}) {
                rays.push_back(Ray{Point3(0.0f), target});
                rays.push_back(Ray{target, target - centre});
                rays.push_back(Ray{target, centre - target});
            }
        }
        // Watertight only: the other two tests' own rounding at 3e4 differs between structures by more than
        // same_hit's tolerance.
        const TriangleTest watertight[] = {TriangleTest::watertight};
        check_all_methods("far sphere of radius " + std::to_string(radius), sphere, rays, false, false, watertight);
    }
}

TEST_CASE("empty and single-triangle meshes", "[accel]") {
    TriangleMesh empty;
    TriangleMesh one;
    one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    one.triangles = {{0, 1, 2}};
    const Ray down{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}};
    for (const std::string& method : accelerator_methods()) {
        INFO(method);
        const auto e = make_accelerator(method, empty);
        MeshHit h;
        CHECK_FALSE(e->intersect(down, h));
        CHECK_FALSE(e->occluded(down));
        const auto s = make_accelerator(method, one);
        REQUIRE(s->intersect(down, h));
        CHECK(h.primitive == 0);
        CHECK(h.t == Approx(1.0f));
        CHECK(h.u == Approx(0.25f));
        CHECK(s->occluded(down));
        CHECK_FALSE(s->occluded(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 0.5f}));
        CHECK_FALSE(s->intersect(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}, 0.7f, 0.7f}, h));  // tmin = tmax
        CHECK_FALSE(s->intersect(Ray{{0.25f, 0.25f, 1.0f}, {std::nanf(""), 0.0f, -1.0f}}, h));
        CHECK_FALSE(s->intersect(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, 0.0f}}, h));
    }
}

TEST_CASE("unknown methods list the known ones", "[accel]") {
    const TriangleMesh one = test::icosphere(0);
    CHECK_THROWS_WITH(make_accelerator("kd-magic", one), Catch::Matchers::Contains("kd-sah, kd-sah-binned"));
}

TEST_CASE("kd-tree leaves run at every width this CPU has and refuse the others by name", "[accel]") {
    const std::vector<int> widths = kd_leaf_widths();
    REQUIRE(!widths.empty());
    CHECK(widths.front() == 4);
    const TriangleMesh sphere = test::icosphere(2);
    BuildOptions options;
    CHECK(make_kd_tree("kd-sah", sphere, options)->stats().leaf_width == widths.back());  // 0: the widest
    for (int width : widths) {
        options.leaf_width = width;
        CHECK(make_kd_tree("kd-sah", sphere, options)->stats().leaf_width == width);
    }
    options.leaf_width = 3;
    CHECK_THROWS_WITH(make_kd_tree("kd-sah", sphere, options), Catch::Matchers::Contains("width 3"));
    if (widths.back() != 8) {
        options.leaf_width = 8;
        CHECK_THROWS_WITH(make_kd_tree("kd-sah", sphere, options), Catch::Matchers::Contains("AVX2"));
    }
}
