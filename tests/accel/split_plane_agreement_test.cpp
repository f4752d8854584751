// Rays that meet a mesh exactly at its vertices and edge midpoints: there kd-tree split planes fall (the
// SAH puts planes at triangle bounds), a hit lies on the plane, and rounding decides which side of it the
// walk and the clipped triangle bounds see. Every structure must then agree with brute force, the
// watertight test guaranteeing that a ray through a shared vertex or edge hits at least one triangle.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/core/rng.hpp>

#include <catch2/catch.hpp>

#include "agreement.hpp"
#include "sample_scale.hpp"
#include "test_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

using namespace rtlab;

namespace {

// Debug and sanitizer builds trace a quarter of the rays: the sets keep their hard cases, the run stays
// short. Sanitizer builds also take the big meshes at a quarter of their triangles (kBigGrid, kBigIcosphere):
// their builds, not the rays, took most of a minute each there.
#if !defined(NDEBUG) || defined(__SANITIZE_ADDRESS__)
constexpr int kRayDivisor = 4;
#else
constexpr int kRayDivisor = 1;
#endif

constexpr int kBigGrid = test::kSanitized ? 112 : 224;   // squares a side: 100,352 triangles (25,088)
constexpr int kBigIcosphere = test::kSanitized ? 5 : 6;  // subdivisions: 81,920 triangles (20,480)

constexpr float kSpacing = 1.0f / 128.0f;  // 2^-7: every vertex and edge midpoint is a float exactly

// n x n squares of side 2^-7 centred on the origin in the plane z = 0, two triangles each with the
// diagonal alternating, every vertex at z = +0 or -0 by a checkerboard of its own.
TriangleMesh signed_zero_grid(int n) {
    TriangleMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            m.positions.emplace_back(static_cast<float>(i - n / 2) * kSpacing, static_cast<float>(j - n / 2) * kSpacing,
                                     ((i / 3 + j) % 2 == 0) ? 0.0f : -0.0f);
    auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if ((i + j) % 2 == 0) {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            } else {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                m.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    return m;
}

// Brute force over the triangles that can hold a ray's hit: those whose bounds come within `reach` of the
// point the ray is aimed at. Exact for rays whose every hit lies there (the sets below make sure; a sample
// is checked against brute force over the whole mesh), and thousands of times faster on 100k triangles.
class LocalBruteForce {
public:
    LocalBruteForce(const TriangleMesh& mesh, float reach) : m_mesh(mesh), m_cell(reach) {
        for (std::size_t k = 0; k < mesh.triangle_count(); ++k) {
            const AABB b = mesh.triangle_bounds(k);
            const auto lo = cell(b.lo), hi = cell(b.hi);
            for (int x = lo[0]; x <= hi[0]; ++x)
                for (int y = lo[1]; y <= hi[1]; ++y)
                    for (int z = lo[2]; z <= hi[2]; ++z)
                        m_cells[key({x, y, z})].push_back(static_cast<std::uint32_t>(k));
        }
    }

    // Brute force's answers to rays aimed at targets[r], over the triangles near each target.
    std::vector<test::Answer> answers(std::span<const Ray> rays, std::span<const Point3> targets,
                                      const BuildOptions& options) const {
        std::vector<test::Answer> out(rays.size());
        std::map<std::array<int, 3>, std::unique_ptr<TriangleAccelerator>> local;
        std::vector<TriangleMesh> meshes;
        meshes.reserve(rays.size());
        for (std::size_t r = 0; r < rays.size(); ++r) {
            const auto c = cell(targets[r]);
            auto& accel = local[c];
            if (!accel) {
                TriangleMesh& sub = meshes.emplace_back();
                std::vector<std::uint32_t> near;
                for (int dx = -1; dx <= 1; ++dx)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dz = -1; dz <= 1; ++dz) {
                            const auto it = m_cells.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
                            if (it != m_cells.end()) near.insert(near.end(), it->second.begin(), it->second.end());
                        }
                std::sort(near.begin(), near.end());
                near.erase(std::unique(near.begin(), near.end()), near.end());
                for (std::uint32_t k : near) {
                    const auto base = static_cast<std::uint32_t>(sub.positions.size());
                    for (int v = 0; v < 3; ++v) sub.positions.push_back(m_mesh.corner(k, v));
                    sub.triangles.push_back({base, base + 1, base + 2});
                }
                accel = make_accelerator("brute", sub, options);
            }
            out[r].hit = accel->intersect(rays[r], out[r].closest);
        }
        return out;
    }

private:
    std::array<int, 3> cell(const Point3& p) const {
        return {static_cast<int>(std::floor(p.x / m_cell)), static_cast<int>(std::floor(p.y / m_cell)),
                static_cast<int>(std::floor(p.z / m_cell))};
    }
    static std::uint64_t key(const std::array<int, 3>& c) {
        auto part = [](int v) {
            return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v + (1 << 20))) & 0x1FFFFF;
        };
        return part(c[0]) | part(c[1]) << 21 | part(c[2]) << 42;
    }

    const TriangleMesh& m_mesh;
    float m_cell;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> m_cells;
};

struct RaySet {
    std::vector<Ray> rays;
    std::vector<Point3> targets;
    void add(const Ray& ray, const Point3& target) {
        rays.push_back(ray);
        targets.push_back(target);
    }
};

// Checks every structure against the reference answers, at every leaf width this CPU runs; returns the
// checks made (for the caller's own count check).
void check_methods(const std::string& label, const TriangleMesh& mesh, const RaySet& set,
                   const std::vector<test::Answer>& reference, const std::vector<std::string>& methods) {
    for (int width : kd_leaf_widths()) {
        BuildOptions options;
        options.leaf_width = width;
        for (const std::string& method : methods) {
            // The other structures have no leaf width: once is enough for them.
            if (width != kd_leaf_widths().front() && method.rfind("kd-", 0) != 0) continue;
            if (width != kd_leaf_widths().front() && method == "kd-three-way") continue;
            const auto accel = make_accelerator(method, mesh, options);
            const test::Agreement a = test::compare(*accel, reference, set.rays);
            INFO(label << ", " << method << ", leaf width " << width << ": " << a.mismatches << " closest-hit and "
                       << a.anyhit_mismatches << " any-hit mismatches of " << a.rays << " rays (" << a.hits
                       << " hits)");
            CHECK(a.mismatches == 0);
            CHECK(a.anyhit_mismatches == 0);
        }
    }
}

// Checks the local reference against brute force over the whole mesh on every k-th ray.
void check_reference(const TriangleMesh& mesh, const RaySet& set, const std::vector<test::Answer>& reference,
                     std::size_t k) {
    std::vector<Ray> sample;
    std::vector<test::Answer> expected;
    for (std::size_t r = 0; r < set.rays.size(); r += k) {
        sample.push_back(set.rays[r]);
        expected.push_back(reference[r]);
    }
    const test::Agreement a = test::compare(*make_accelerator("brute", mesh), expected, sample);
    INFO("local against whole-mesh brute force: " << a.mismatches << " of " << a.rays);
    CHECK(a.mismatches == 0);
    CHECK(a.anyhit_mismatches == 0);
}

const std::vector<std::string> kMethods = {"kd-sah",       "kd-sah-binned", "kd-median", "kd-midpoint",
                                           "kd-three-way", "bvh",           "octree"};

// The grid's rays: from both sides of the plane, obliquely, to vertices and to the midpoints of the
// horizontal, vertical and diagonal edges. Half of them come from an offset of small multiples of 2^-6,
// so that origin + 1 * direction is the target exactly; the other half from random float directions,
// which pass the target within rounding. Every third ray is bounded like a shadow ray ending at the target:
// tmax a few ulps past t = 1.
RaySet grid_rays(int n, int count) {
    RaySet set;
    Rng rng(11);
    for (int r = 0; r < count; ++r) {
        const int i = 1 + static_cast<int>(rng.uniform_u32(static_cast<std::uint32_t>(n - 2)));
        const int j = 1 + static_cast<int>(rng.uniform_u32(static_cast<std::uint32_t>(n - 2)));
        Point3 target(static_cast<float>(i - n / 2) * kSpacing, static_cast<float>(j - n / 2) * kSpacing, 0.0f);
        switch (r % 4) {
            case 0:
                break;  // vertex
            case 1:
                target.x += 0.5f * kSpacing;
                break;  // horizontal edge
            case 2:
                target.y += 0.5f * kSpacing;
                break;  // vertical edge
            default:
                target += Vec3(0.5f * kSpacing, 0.5f * kSpacing, 0.0f);  // a diagonal
        }
        const float side = (r / 4) % 2 == 0 ? 1.0f : -1.0f;
        Vec3 offset;
        if ((r / 8) % 2 == 0) {
            offset = Vec3(static_cast<float>(static_cast<int>(rng.uniform_u32(129)) - 64) / 64.0f,
                          static_cast<float>(static_cast<int>(rng.uniform_u32(129)) - 64) / 64.0f,
                          side * static_cast<float>(8 + rng.uniform_u32(57)) / 64.0f);
        } else {
            offset =
                Vec3(2.0f * rng.uniform() - 1.0f, 2.0f * rng.uniform() - 1.0f, side * (0.1f + 0.9f * rng.uniform()));
        }
        const float tmax = r % 3 == 0 ? 1.0f + 4.0f * std::numeric_limits<float>::epsilon() : kInfinity;
        set.add(Ray{target + offset, -offset, 0.0f, tmax}, target);
    }
    return set;
}

// The grid set: n x n squares, `count` rays; checks `methods` and reports Moller-Trumbore's misses.
void check_grid(int n, int count, const std::vector<std::string>& methods) {
    const TriangleMesh grid = signed_zero_grid(n);
    const RaySet set = grid_rays(n, count);
    // Every hit lies within rounding of the target: the ray crosses the plane z = 0 there only.
    const LocalBruteForce local(grid, 2.0f * kSpacing);
    const std::vector<test::Answer> reference = local.answers(set.rays, set.targets, BuildOptions{});
    check_reference(grid, set, reference, 200);
    std::size_t hits = 0, unbounded = 0, unbounded_hits = 0;
    for (std::size_t r = 0; r < set.rays.size(); ++r) {
        hits += reference[r].hit;
        if (set.rays[r].tmax == kInfinity) ++unbounded, unbounded_hits += reference[r].hit;
    }
    INFO("grid of " << grid.triangle_count() << " triangles: brute force hits " << hits << " of " << set.rays.size());
    // Watertight: every unbounded ray hits; most bounded ones end past their hit.
    REQUIRE(unbounded_hits == unbounded);
    REQUIRE(hits > set.rays.size() * 9 / 10);
    check_methods("grid", grid, set, reference, methods);

    // Moller-Trumbore is not watertight: rays through shared vertices and edges slip between triangles
    // (measured on the 100k grid, release build: 408 of the 40,000 unbounded rays miss). Reported, not
    // checked: it is a property of the test, not of the structures.
    BuildOptions moller;
    moller.triangle_test = TriangleTest::moller;
    const std::vector<test::Answer> moller_reference = local.answers(set.rays, set.targets, moller);
    std::size_t moller_misses = 0;
    for (std::size_t r = 0; r < set.rays.size(); ++r)
        moller_misses += set.rays[r].tmax == kInfinity && !moller_reference[r].hit;
    WARN("grid of " << grid.triangle_count() << " triangles: Moller-Trumbore brute force misses " << moller_misses
                    << " of " << unbounded << " unbounded rays (watertight: 0)");
}

// The icosphere set: 20 * 4^subdivisions triangles, `count` rays; checks `methods`.
void check_icosphere(int subdivisions, int count, const std::vector<std::string>& methods) {
    const TriangleMesh sphere = test::icosphere(subdivisions);
    RaySet set;
    Rng rng(17);
    for (int r = 0; r < count; ++r) {
        const auto k = rng.uniform_u32(static_cast<std::uint32_t>(sphere.triangle_count()));
        const int v = static_cast<int>(rng.uniform_u32(3));
        const Point3 a = sphere.corner(k, v), b = sphere.corner(k, (v + 1) % 3);
        const Point3 target = r % 2 == 0 ? a : 0.5f * (a + b);
        // From outside, within 60 degrees of the outward radius: the faces at the target are within a few
        // degrees of its tangent plane, so the ray reaches the target before any other part of the
        // (convex) sphere.
        Vec3 tangent(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f);
        const Vec3 radial = glm::normalize(Vec3(target));
        tangent -= glm::dot(tangent, radial) * radial;
        if (glm::length(tangent) > 0.0f) tangent = glm::normalize(tangent) * (1.7f * rng.uniform());
        const Vec3 offset = (radial + tangent) * (0.25f + rng.uniform());
        set.add(Ray{target + offset, -offset}, target);
    }
    const LocalBruteForce local(sphere, 4.0f / static_cast<float>(1 << subdivisions));
    const std::vector<test::Answer> reference = local.answers(set.rays, set.targets, BuildOptions{});
    check_reference(sphere, set, reference, 250);
    std::size_t hits = 0;
    for (const test::Answer& a : reference) hits += a.hit;
    INFO("icosphere of " << sphere.triangle_count() << " triangles: brute force hits " << hits << " of "
                         << set.rays.size());
    REQUIRE(hits == set.rays.size());
    check_methods("icosphere", sphere, set, reference, methods);
}

}  // namespace

TEST_CASE("grid vertices and edge midpoints hit obliquely on split planes with +0 and -0", "[accel]") {
    check_grid(kBigGrid, 60000 / kRayDivisor, kMethods);
}

TEST_CASE("a closed icosphere hit at its vertices and edge midpoints", "[accel]") {
    check_icosphere(kBigIcosphere, 100000 / kRayDivisor, kMethods);
}

// kd-sah-naive takes minutes on 100k triangles (O(N^2) per node): it gets the same sets, smaller.
TEST_CASE("kd-sah-naive on a smaller grid and icosphere hit at vertices and edge midpoints", "[accel]") {
    check_grid(48, 20000 / kRayDivisor, {"kd-sah-naive", "kd-sah"});      // 4,608 triangles
    check_icosphere(4, 20000 / kRayDivisor, {"kd-sah-naive", "kd-sah"});  // 5,120 triangles
}

// Each vertex belongs to one square only, so no neighbour catches a ray the walk loses at a vertex where an x
// and a y split plane cross: widening only the root interval passed every other test here and missed 69 of
// 27,166 hits with kd-sah on this set.
TEST_CASE("isolated squares hit exactly at their corner vertices agree with brute force", "[accel]") {
    const int n = 64;
    const TriangleMesh m = test::isolated_squares(n, kSpacing);
    Rng rng(5);
    std::vector<Ray> rays;
    for (int r = 0; r < 40000 / kRayDivisor; ++r) {
        const int i = 1 + static_cast<int>(rng.uniform_u32(n - 2)), j = 1 + static_cast<int>(rng.uniform_u32(n - 2));
        const Point3 target(static_cast<float>(i - n / 2) * kSpacing, static_cast<float>(j - n / 2) * kSpacing, 0.0f);
        const Vec3 d(rng.uniform() - 0.5f, rng.uniform() - 0.5f, (r % 2 ? 1.0f : -1.0f) * (0.1f + rng.uniform()));
        Ray ray;
        ray.origin = target - d * 3.0f;
        ray.direction = d;
        rays.push_back(ray);
    }
    const auto reference = test::answers(*make_accelerator("brute", m), rays);
    int hits = 0;
    for (const auto& a : reference) hits += a.hit;
    for (const std::string method : {"kd-sah", "kd-median", "kd-midpoint"}) {
        const test::Agreement a = test::compare(*make_accelerator(method, m), reference, rays);
        INFO(method << ": " << a.mismatches << " closest and " << a.anyhit_mismatches << " any-hit mismatches of "
                    << a.rays << " rays, " << hits << " hits");
        CHECK(a.mismatches == 0);
        CHECK(a.anyhit_mismatches == 0);
    }
}
