// Packet queries (intersect_packet, occluded_packet) against the same structure's single-ray answers, bit
// for bit: the kd-trees walk coherent rays together, and each ray must still get exactly what its own walk
// gives (t, triangle, u, v; ties between triangles at equal t included). The inputs are the ones where
// single walks fail: rays through vertices and edges, rays in split planes, axis-parallel rays with +0 and
// -0 components, empty and negative intervals, NaN, tiny and huge coordinates; then coherent camera tiles and
// shadow rays towards one point, packets of mixed octants and packets with fewer rays than lanes.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/core/rng.hpp>

#include <catch2/catch.hpp>

#include "camera_tiles.hpp"
#include "test_meshes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

#if !defined(NDEBUG) || defined(__SANITIZE_ADDRESS__)
constexpr int kRayDivisor = 4;  // debug and sanitizer builds: fewer rays, the same hard cases
#else
constexpr int kRayDivisor = 1;
#endif

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

struct Differences {
    std::size_t rays = 0, hits = 0, closest = 0, any = 0;
};

// Traces `rays` in consecutive packets of `size` and compares every answer with the single-ray one.
Differences compare_packets(const TriangleAccelerator& accel, std::span<const Ray> rays, std::size_t size) {
    std::vector<MeshHit> hits(rays.size());
    std::vector<std::uint8_t> blocked(rays.size(), 2);
    for (std::size_t i = 0; i < rays.size(); i += size) {
        const std::size_t n = std::min(size, rays.size() - i);
        accel.intersect_packet(rays.subspan(i, n), std::span<MeshHit>(hits).subspan(i, n));
        accel.occluded_packet(rays.subspan(i, n), std::span<std::uint8_t>(blocked).subspan(i, n));
    }
    Differences d;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        MeshHit single;
        const bool hit = accel.intersect(rays[i], single);
        if (!hit) single = MeshHit{};
        const MeshHit& p = hits[i];
        ++d.rays;
        d.hits += hit;
        d.closest += !(same_bits(p.t, single.t) && p.primitive == single.primitive && same_bits(p.u, single.u) &&
                       same_bits(p.v, single.v));
        d.any += blocked[i] != (accel.occluded(rays[i]) ? 1 : 0);
    }
    return d;
}

// The kd-trees over triangles, every triangle test and leaf width, each against its own single rays in
// packets of 8 (4 x 2 tiles when the rays come in tile order), of every size up to 8 and of 13 (more than
// one packet per call). Also a kd-sah tree whose splits cost 100 triangle tests ("big leaves"): leaves of many
// triangle packets, whose boxes the packet walk tests before their triangles.
void check_kd_packets(const std::string& label, const TriangleMesh& mesh, const std::vector<Ray>& rays,
                      const std::vector<std::string>& methods = {"kd-sah", "kd-sah-binned", "kd-median",
                                                                 "kd-midpoint"}) {
    for (TriangleTest test : {TriangleTest::watertight, TriangleTest::moller, TriangleTest::plane}) {
        BuildOptions options;
        options.triangle_test = test;
        for (int width : kd_leaf_widths()) {
            options.leaf_width = width;
            std::vector<std::string> names = methods;
            names.push_back("big leaves");
            for (const std::string& method : names) {
                const auto accel = method == "big leaves"
                                       ? make_kd_tree("kd-sah", mesh, options, KdCostModel(1.0f, 0.01f))
                                       : make_accelerator(method, mesh, options);
                if (method == "big leaves" && mesh.triangle_count() >= 64)
                    CHECK(accel->stats().mean_leaf_primitives >= 2.0 * width);
                for (std::size_t size : {8, 1, 3, 5, 7, 13}) {
                    // Every size on the kd-sah tree; the other trees in tiles of 8 only.
                    if (size != 8 && method != methods.front()) continue;
                    const Differences d = compare_packets(*accel, rays, size);
                    INFO(label << ", " << method << ", " << to_string(test) << ", leaf width " << width
                               << ", packets of " << size << ": " << d.closest << " closest-hit and " << d.any
                               << " any-hit differences of " << d.rays << " rays (" << d.hits << " hits)");
                    CHECK(d.closest == 0);
                    CHECK(d.any == 0);
                }
            }
        }
    }
}

// Shadow rays from the closest hits of `primary` (in their order, misses left out) towards `light`,
// ending just before it.
std::vector<Ray> shadow_rays(const TriangleAccelerator& accel, const std::vector<Ray>& primary, const Point3& light) {
    std::vector<Ray> rays;
    for (const Ray& r : primary) {
        MeshHit h;
        if (!accel.intersect(r, h)) continue;
        const Point3 p = r.at(h.t);
        rays.push_back(Ray{p, light - p, 1e-4f, 1.0f});
    }
    return rays;
}

// Rays over the lattice box [lo, lo + 4 cell]^3 like the stability tests': along the axes on lattice planes
// with +0 and -0 components, inside face planes, grazing them, and random.
std::vector<Ray> lattice_rays(const Point3& lo, float cell, int count, std::uint32_t seed) {
    Rng rng(seed);
    const float size = 4.0f * cell;
    auto on_plane = [&](int a) { return lo[a] + cell * static_cast<float>(rng.uniform_u32(5)); };
    auto anywhere = [&](int a) { return lo[a] - 0.25f * size + 1.5f * size * rng.uniform(); };
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const int a = static_cast<int>(rng.uniform_u32(3)), b = (a + 1) % 3, c = (a + 2) % 3;
        Point3 o;
        Vec3 d(rng.uniform_u32(2) ? 0.0f : -0.0f);
        switch (i % 4) {
            case 0:  // along axis a, on lattice planes
                o[a] = rng.uniform_u32(2) ? lo[a] - size : lo[a] + 2.0f * size;
                o[b] = on_plane(b);
                o[c] = rng.uniform_u32(2) ? on_plane(c) : anywhere(c);
                d[a] = o[a] < lo[a] ? 1.0f : -1.0f;
                break;
            case 1:    // inside a face plane
            case 2: {  // or 1e-6 off it
                o[c] = on_plane(c);
                o[a] = anywhere(a);
                o[b] = anywhere(b);
                const float phi = 6.2831853f * rng.uniform();
                d[a] = std::cos(phi);
                d[b] = std::sin(phi);
                if (i % 4 == 2) d[c] = rng.uniform_u32(2) ? 1e-6f : -1e-6f;
                break;
            }
            default:
                for (int k = 0; k < 3; ++k) o[k] = anywhere(k);
                d = Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f);
        }
        rays.push_back(Ray{o, d});
    }
    return rays;
}

// The rays grouped by the sign bits of their directions: packets of one octant whose rays go anywhere,
// so the lanes part and meet at every node.
std::vector<Ray> by_octant(std::vector<Ray> rays) {
    auto octant = [](const Ray& r) {
        return std::signbit(r.direction.x) | std::signbit(r.direction.y) << 1 | std::signbit(r.direction.z) << 2;
    };
    std::stable_sort(rays.begin(), rays.end(), [&](const Ray& a, const Ray& b) { return octant(a) < octant(b); });
    return rays;
}

}  // namespace

TEST_CASE("kd packets answer as single rays in split planes along axes and grazing faces of a cube lattice",
          "[accel]") {
    for (float scale : {1.0f, 1e-6f, 1e4f}) {
        const Point3 lo = scale * Point3(100.0f, -50.0f, 25.0f);  // coordinates ~1e-4, ~1e2 and ~1e6
        const TriangleMesh lattice = test::cube_lattice(scale, lo);
        std::vector<Ray> rays = lattice_rays(lo, scale, 1600 / kRayDivisor, 3);
        const std::vector<Ray> sorted = by_octant(rays);
        rays.insert(rays.end(), sorted.begin(), sorted.end());
        // Coherent tiles of axis-parallel rays on lattice lines, and camera tiles through the lattice.
        for (float zero : {0.0f, -0.0f})
            for (int i = 0; i <= 8; ++i)
                for (int j = 0; j <= 8; ++j)
                    rays.push_back(
                        Ray{lo + scale * Vec3(0.5f * static_cast<float>(i), 0.5f * static_cast<float>(j), 6.0f),
                            Vec3(zero, zero, -1.0f)});
        const std::vector<Ray> tiles =
            test::camera_tiles(lo + scale * Vec3(2.0f, 2.5f, 12.0f), lo + scale * Vec3(2.0f), 5.0f * scale, 24);
        rays.insert(rays.end(), tiles.begin(), tiles.end());
        check_kd_packets("cube lattice at scale " + std::to_string(scale), lattice, rays,
                         {"kd-sah", "kd-sah-binned", "kd-sah-naive", "kd-median", "kd-midpoint"});
    }
}

TEST_CASE("kd packets answer as single rays for flat and stacked coplanar grids hit at vertices and edges", "[accel]") {
    const TriangleMesh grid = test::coplanar_grid(32, 0.5f);
    TriangleMesh stacked = grid;  // four exact copies: ties at equal t between four triangles
    for (int k = 1; k < 4; ++k) {
        const auto base = static_cast<std::uint32_t>(stacked.positions.size());
        stacked.positions.insert(stacked.positions.end(), grid.positions.begin(), grid.positions.end());
        for (const auto& t : grid.triangles) stacked.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    std::vector<Ray> rays;
    // Tiles whose rays pass exactly through vertices and edge midpoints (origin + 1 * direction on them),
    // from above and below, and rays in the grid's plane.
    for (float side : {1.0f, -1.0f})
        for (int ty = 0; ty < 32; ty += 2)
            for (int tx = 0; tx < 32; tx += 4)
                for (int y = ty; y < ty + 2; ++y)
                    for (int x = tx; x < tx + 4; ++x) {
                        const Point3 target(0.5f * static_cast<float>(x), 0.5f * static_cast<float>(y) + 4.0f, 0.5f);
                        const Point3 eye(7.25f, 11.5f, 0.5f + side * 6.0f);
                        const bool shadow = (tx / 4 + ty / 2) % 3 == 0;  // bounded like a shadow ray ending there
                        rays.push_back(Ray{eye, target - eye, 0.0f,
                                           shadow ? 1.0f + 4.0f * std::numeric_limits<float>::epsilon() : kInfinity});
                    }
    for (int i = 0; i < 64; ++i) {
        const float y = 0.25f * static_cast<float>(i);
        rays.push_back(Ray{{-1.0f, y, 0.5f}, {1.0f, 0.0f, i % 2 ? 0.0f : -0.0f}});
        rays.push_back(Ray{{-1.0f, -1.0f + y, 0.5f}, {1.0f, 1.0f, i % 3 ? 0.0f : -0.0f}});
    }
    check_kd_packets("coplanar grid", grid, rays);
    check_kd_packets("4 stacked coplanar grids", stacked, rays);
}

// Squares whose corners belong to one square only, hit exactly at those corners (the set where widening
// only the root interval lost hits, split_plane_agreement_test.cpp): only the per-node margins keep the
// hits there, so each lane must have them. Packets of one octant, of rays from anywhere, and tiles of rays
// from one eye at the corners.
TEST_CASE("kd packets answer as single rays at corner vertices of isolated squares", "[accel]") {
    const int n = 64;
    const float spacing = 1.0f / 128.0f;
    const TriangleMesh m = test::isolated_squares(n, spacing);
    Rng rng(5);
    std::vector<Ray> rays;
    auto corner = [&] {
        const int i = 1 + static_cast<int>(rng.uniform_u32(n - 2)), j = 1 + static_cast<int>(rng.uniform_u32(n - 2));
        return Point3(static_cast<float>(i - n / 2) * spacing, static_cast<float>(j - n / 2) * spacing, 0.0f);
    };
    for (int r = 0; r < 16000 / kRayDivisor; ++r) {
        const Point3 target = corner();
        const Vec3 d(rng.uniform() - 0.5f, rng.uniform() - 0.5f, (r % 2 ? 1.0f : -1.0f) * (0.1f + rng.uniform()));
        rays.push_back(Ray{target - d * 3.0f, d});
    }
    rays = by_octant(std::move(rays));
    for (int r = 0; r < 8000 / kRayDivisor; ++r) {
        const Point3 eye = Point3(0.1f, -0.05f, 0.3f);
        rays.push_back(Ray{eye, corner() - eye});
    }
    check_kd_packets("isolated squares", m, rays);
}

TEST_CASE("kd packets answer as single rays for camera tiles and shadow rays on an icosphere and triangle soup",
          "[accel]") {
    const TriangleMesh sphere = test::icosphere(4);
    const TriangleMesh soup = test::random_soup(3000, 5, 1.5f);
    Rng rng(9);
    for (const TriangleMesh* mesh : {&sphere, &soup}) {
        const AABB b = mesh->bounds();
        const Point3 c = b.center();
        const float diag = glm::length(b.extent());
        std::vector<Ray> rays;
        for (int view = 0; view < 6; ++view) {
            // From random directions; the last two with a tiny field, where the rays of a tile nearly coincide.
            const Vec3 away = glm::normalize(Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f));
            const Point3 eye = c + 1.5f * diag * away;
            const float field = view < 4 ? diag : 1e-5f * diag;
            const std::vector<Ray> tiles = test::camera_tiles(eye, c, field, 32 / (view < 4 ? 1 : 4));
            rays.insert(rays.end(), tiles.begin(), tiles.end());
        }
        // Shadow rays from the hits towards a point above the mesh and one inside it.
        const auto kd = make_accelerator("kd-sah", *mesh);
        for (const Point3& light : {c + diag * Vec3(0.25f, 1.0f, 0.5f), c}) {
            const std::vector<Ray> shadows = shadow_rays(*kd, rays, light);
            rays.insert(rays.end(), shadows.begin(), shadows.end());
        }
        check_kd_packets(mesh == &sphere ? "icosphere" : "triangle soup", *mesh, rays);
    }
}

TEST_CASE("kd packets answer invalid rays and empty and negative intervals as single rays do", "[accel]") {
    const TriangleMesh sphere = test::icosphere(3);
    const Point3 o(0.1f, 0.2f, -3.0f);
    const Vec3 d(0.0f, 0.0f, 1.0f);
    // Each special ray among good rays of its octant: the packet must leave its lane out without
    // disturbing the others.
    const std::vector<Ray> special = {
        Ray{Point3(kNaN, 0.0f, -3.0f), d},
        Ray{o, Vec3(0.0f, kNaN, 1.0f)},
        Ray{Point3(0.0f, 0.0f, -kInfinity), d},
        Ray{o, Vec3(0.0f, 0.0f, kInfinity)},
        Ray{o, Vec3(0.0f)},
        Ray{o, Vec3(-0.0f, 0.0f, -0.0f)},
        Ray{o, d, 5.0f, 1.0f},                   // tmin > tmax
        Ray{o, d, 2.0f, 2.0f},                   // tmin = tmax
        Ray{o, d, 2.5f, 2.5f},                   // tmin = tmax inside the sphere
        Ray{o, d, -10.0f, 2.5f},                 // negative tmin, the origin outside
        Ray{Point3(0.0f), d, -0.5f, kInfinity},  // negative tmin from inside: the hit behind the origin is not in
        Ray{Point3(0.0f), d, -1.5f, kInfinity},  // ... but is here
        Ray{o, d, kNaN, 10.0f},
        Ray{o, d, 0.0f, kNaN},
        Ray{o, d, 0.0f, 2.0f + 1e-3f},  // bounded just past the near hit
        Ray{o, d * 1e-30f},             // tiny and huge directions
        Ray{o, d * 1e30f},
        Ray{o * 1e20f, -o},  // far origin
    };
    std::vector<Ray> rays;
    for (const Ray& s : special)
        for (int lane = 0; lane < 8; ++lane) {
            for (int k = 0; k < 8; ++k) {
                const float dx = 0.01f * static_cast<float>(k);
                rays.push_back(k == lane ? s : Ray{o, Vec3(dx, 0.02f, 1.0f)});
            }
        }
    check_kd_packets("special rays", sphere, rays);
}

TEST_CASE("packets of mixed octants and partial packets answer as single rays", "[accel]") {
    const TriangleMesh sphere = test::icosphere(3);
    Rng rng(21);
    std::vector<Ray> rays;
    // Camera tiles centred on the sphere's centre: tiles at the middle straddle the octant boundaries.
    const std::vector<Ray> tiles = test::camera_tiles(Point3(0.0f, 0.0f, 3.0f), Point3(0.0f), 2.0f, 16);
    rays.insert(rays.end(), tiles.begin(), tiles.end());
    // Random rays: every packet of them mixes octants.
    for (int i = 0; i < 800 / kRayDivisor; ++i) {
        const Point3 o(4.0f * rng.uniform() - 2.0f, 4.0f * rng.uniform() - 2.0f, 4.0f * rng.uniform() - 2.0f);
        rays.push_back(Ray{o, Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f)});
    }
    check_kd_packets("mixed octants", sphere, rays);
}

TEST_CASE("the other methods' packet queries give their single-ray answers", "[accel]") {
    const TriangleMesh sphere = test::icosphere(3);
    std::vector<Ray> rays = test::camera_tiles(Point3(0.3f, 0.2f, 3.0f), Point3(0.0f), 2.5f, 16);
    const std::vector<Ray> shadows = shadow_rays(*make_accelerator("brute", sphere), rays, Point3(1.0f, 3.0f, 2.0f));
    rays.insert(rays.end(), shadows.begin(), shadows.end());
    rays.push_back(Ray{Point3(0.0f, 0.0f, -3.0f), Vec3(0.0f)});
    for (const std::string& method : accelerator_methods()) {
        const auto accel = make_accelerator(method, sphere);
        const Differences d = compare_packets(*accel, rays, 8);
        INFO(method << ": " << d.closest << " closest-hit and " << d.any << " any-hit differences of " << d.rays
                    << " rays (" << d.hits << " hits)");
        CHECK(d.hits > d.rays / 4);
        if (method == "embree") {
            // rtcIntersect8 runs Embree's packet kernels, whose arithmetic may differ from rtcIntersect1's
            // in the last bits: the same triangles are hit, within rounding.
            CHECK(d.any == 0);
            std::vector<MeshHit> hits(rays.size());
            accel->intersect_packet(rays, hits);
            std::size_t other = 0;
            for (std::size_t i = 0; i < rays.size(); ++i) {
                MeshHit single;
                const bool hit = accel->intersect(rays[i], single);
                other += hit != hits[i].hit() || (hit && (single.primitive != hits[i].primitive ||
                                                          std::abs(single.t - hits[i].t) > 1e-5f * single.t));
            }
            CHECK(other == 0);
        } else {
            CHECK(d.closest == 0);
            CHECK(d.any == 0);
        }
    }
}
