// Acceleration structures where they are known to fail, against brute force on the same triangle test:
// rays along the axes and inside the planes a kd-tree splits on, grazing rays, flat meshes (a zero-thickness
// box), stacked coplanar copies, degenerate triangles among good ones, and meshes far from the origin.
#include "record.hpp"

#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/hit_agreement.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace rtlab;
using rtlab::stability::record;

namespace {

void add_quad(TriangleMesh& m, const Point3& o, const Vec3& a, const Vec3& b) {
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {o, o + a, o + a + b, o + b});
    m.triangles.push_back({base, base + 1, base + 2});
    m.triangles.push_back({base, base + 2, base + 3});
}

/// Unit cubes on a 4 x 4 x 4 lattice (every other cell), each face two triangles: every face lies on a
/// plane a kd-tree is likely to split on, and many faces of neighbours lie in one plane.
TriangleMesh cube_lattice(float scale, const Point3& offset) {
    TriangleMesh m;
    for (int x = 0; x < 4; ++x)
        for (int y = 0; y < 4; ++y)
            for (int z = 0; z < 4; ++z) {
                if ((x + y + z) % 2) continue;
                const Point3 o = offset + scale * Vec3(x, y, z);
                const float s = scale;
                add_quad(m, o, Vec3(0, s, 0), Vec3(s, 0, 0));
                add_quad(m, o + Vec3(0, 0, s), Vec3(s, 0, 0), Vec3(0, s, 0));
                add_quad(m, o, Vec3(s, 0, 0), Vec3(0, 0, s));
                add_quad(m, o + Vec3(0, s, 0), Vec3(0, 0, s), Vec3(s, 0, 0));
                add_quad(m, o, Vec3(0, 0, s), Vec3(0, s, 0));
                add_quad(m, o + Vec3(s, 0, 0), Vec3(0, s, 0), Vec3(0, 0, s));
            }
    return m;
}

/// An 8 x 8 grid of quads in the plane z = z0, `layers` times (layer k at z0 + k * gap; gap 0 stacks exact copies).
TriangleMesh flat_grid(float scale, int layers, float gap) {
    TriangleMesh m;
    for (int k = 0; k < layers; ++k)
        for (int i = 0; i < 8; ++i)
            for (int j = 0; j < 8; ++j)
                add_quad(
                    m,
                    Point3(scale * static_cast<float>(i), scale * static_cast<float>(j), static_cast<float>(k) * gap),
                    Vec3(scale, 0, 0), Vec3(0, scale, 0));
    return m;
}

enum class RayKind { axis, in_plane, grazing, random };
const char* kind_name(RayKind k) {
    switch (k) {
        case RayKind::axis:
            return "axis-parallel rays on split planes";
        case RayKind::in_plane:
            return "rays inside face planes";
        case RayKind::grazing:
            return "grazing rays (1e-6 off a face plane)";
        case RayKind::random:
            return "random rays";
    }
    return "";
}

/// Rays over a box [lo, lo + size]^3 whose coordinates fall on the lattice planes lo + k * step (k integer)
/// for the kinds that need them.
std::vector<Ray> make_rays(RayKind kind, const Point3& lo, float size, float step, int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::uniform_int_distribution<int> axis(0, 2), sign(0, 1);
    const int planes = static_cast<int>(std::lround(size / step));
    std::uniform_int_distribution<int> lattice(0, planes);
    auto on_plane = [&](int a) { return lo[a] + step * static_cast<float>(lattice(rng)); };
    auto anywhere = [&](int a) { return lo[a] - 0.25f * size + 1.5f * size * u(rng); };
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const int a = axis(rng), b = (a + 1) % 3, c = (a + 2) % 3;
        Point3 o;
        Vec3 d(0.0f);
        switch (kind) {
            case RayKind::axis:  // along axis a, the other two coordinates on lattice planes (or one of them)
                o[a] = sign(rng) ? lo[a] - size : lo[a] + 2.0f * size;
                o[b] = on_plane(b);
                o[c] = u(rng) < 0.5f ? on_plane(c) : anywhere(c);
                d[a] = o[a] < lo[a] ? 1.0f : -1.0f;
                break;
            case RayKind::in_plane:  // inside the plane x_c = lattice value, any direction in it
            case RayKind::grazing: {
                o[c] = on_plane(c);
                o[a] = anywhere(a);
                o[b] = anywhere(b);
                const float phi = 6.2831853f * u(rng);
                d[a] = std::cos(phi);
                d[b] = std::sin(phi);
                if (kind == RayKind::grazing) d[c] = (sign(rng) ? 1e-6f : -1e-6f);
                break;
            }
            case RayKind::random:
                for (int k = 0; k < 3; ++k) o[k] = anywhere(k);
                d = Vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
                break;
        }
        rays.push_back({o, d, 0.0f, kInfinity});
    }
    return rays;
}

struct Outcome {
    std::int64_t tried = 0, mismatches = 0;
};

Outcome compare(const TriangleAccelerator& accel, const TriangleAccelerator& brute, const std::vector<Ray>& rays) {
    Outcome o;
    for (const Ray& r : rays) {
        MeshHit a, b;
        const bool ha = accel.intersect(r, a), hb = brute.intersect(r, b);
        const bool oa = accel.occluded(r), ob = brute.occluded(r);
        ++o.tried;
        o.mismatches += !same_hit(ha, a, hb, b) || oa != ob || oa != hb;
    }
    return o;
}

/// Every method against brute force on one mesh and ray set; methods with the watertight test are held to
/// 0 mismatches except Embree, which runs its own triangle test (measured only).
/// kd_trees: the kd-tree methods of the factory ("kd-sah", ..., not "kd-three-way"), in cases of their own
/// (they leaked at split planes until issue 12: a ray lying in a split plane lost the far child's closer hit
/// when its closest-hit walk stopped at the first stacked node beginning past a hit); otherwise every other
/// method.
bool is_split_plane_kd(const std::string& method) { return method.rfind("kd-", 0) == 0 && method != "kd-three-way"; }

void mismatch_rows(bool kd_trees, const std::string& input, const TriangleMesh& mesh, const std::vector<Ray>& rays) {
    const auto brute = make_accelerator("brute", mesh);
    for (const std::string& method : accelerator_methods()) {
        if (method == "brute" || is_split_plane_kd(method) != kd_trees) continue;
        const auto accel = make_accelerator(method, mesh);
        const Outcome o = compare(*accel, *brute, rays);
        const bool promises = method != "embree";
        record({"accelerator", method, input, o.tried, o.mismatches,
                "closest or any-hit answer differs from brute force", std::nan(""),
                promises ? "0 mismatches" : "none (own triangle test)"});
        INFO(method << " on " << input << ": " << o.mismatches << " of " << o.tried);
        if (promises) CHECK(o.mismatches == 0);
    }
}

}  // namespace

static void lattice_rays_case(bool kd_trees) {
    const TriangleMesh mesh = cube_lattice(1.0f, Point3(0.0f));
    for (RayKind kind : {RayKind::axis, RayKind::in_plane, RayKind::grazing, RayKind::random})
        mismatch_rows(kd_trees, std::string(kind_name(kind)) + ", cube lattice", mesh,
                      make_rays(kind, Point3(0.0f), 4.0f, 1.0f, 3000, 11 + static_cast<int>(kind)));
}

TEST_CASE("accelerators agree with brute force for axis-parallel in-plane and grazing rays", "[stability]") {
    lattice_rays_case(false);
}

TEST_CASE("kd-trees: accelerators agree with brute force for axis-parallel in-plane and grazing rays", "[stability]") {
    lattice_rays_case(true);
}

static void flat_and_stacked_case(bool kd_trees) {
    const TriangleMesh flat = flat_grid(0.5f, 1, 0.0f);
    const TriangleMesh stacked = flat_grid(0.5f, 4, 0.0f);
    const TriangleMesh close_layers = flat_grid(0.5f, 4, 1e-6f);
    for (RayKind kind : {RayKind::axis, RayKind::in_plane, RayKind::grazing, RayKind::random}) {
        const auto rays = make_rays(kind, Point3(0.0f), 4.0f, 0.5f, 2000, 21 + static_cast<int>(kind));
        mismatch_rows(kd_trees, std::string(kind_name(kind)) + ", flat mesh (one plane)", flat, rays);
        mismatch_rows(kd_trees, std::string(kind_name(kind)) + ", 4 identical coplanar copies", stacked, rays);
        mismatch_rows(kd_trees, std::string(kind_name(kind)) + ", 4 layers 1e-6 apart", close_layers, rays);
    }
}

TEST_CASE("accelerators agree with brute force on flat and stacked coplanar geometry", "[stability]") {
    flat_and_stacked_case(false);
}

TEST_CASE("kd-trees: accelerators agree with brute force on flat and stacked coplanar geometry", "[stability]") {
    flat_and_stacked_case(true);
}

static void degenerate_case(bool kd_trees) {
    TriangleMesh mesh = cube_lattice(1.0f, Point3(0.0f));
    // Zero-area triangles lying on faces and edges of the lattice, and one with a repeated corner.
    const auto n = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {Point3(0, 0, 0), Point3(2, 0, 0), Point3(4, 0, 0), Point3(1, 1, 1),
                                                 Point3(1, 1, 1), Point3(3, 3, 3)});
    mesh.triangles.push_back({n, n + 1, n + 2});
    mesh.triangles.push_back({n + 3, n + 4, n + 5});
    mesh.triangles.push_back({n + 3, n + 3, n + 3});
    REQUIRE(mesh.degenerate_count() == 3);
    for (RayKind kind : {RayKind::axis, RayKind::random})
        mismatch_rows(kd_trees, std::string(kind_name(kind)) + ", cube lattice + 3 degenerate triangles", mesh,
                      make_rays(kind, Point3(0.0f), 4.0f, 1.0f, 3000, 31 + static_cast<int>(kind)));
}

TEST_CASE("accelerators agree with brute force with degenerate triangles among good ones", "[stability]") {
    degenerate_case(false);
}

TEST_CASE("kd-trees: accelerators agree with brute force with degenerate triangles among good ones", "[stability]") {
    degenerate_case(true);
}

static void far_coordinates_case(bool kd_trees) {
    for (float c : {1e-4f, 1e5f, 1e6f}) {
        // The lattice's cells are 1e-2 of the coordinate's size, so faces stay apart in float.
        const float cell = 1e-2f * c;
        const Point3 lo(c, -0.5f * c, 0.25f * c);
        const TriangleMesh mesh = cube_lattice(cell, lo);
        char name[64];
        std::snprintf(name, sizeof name, ", cube lattice at coordinates ~%g", static_cast<double>(c));
        for (RayKind kind : {RayKind::axis, RayKind::random})
            mismatch_rows(kd_trees, std::string(kind_name(kind)) + name, mesh,
                          make_rays(kind, lo, 4.0f * cell, cell, 2000, 41));
    }
}

TEST_CASE("accelerators agree with brute force at coordinates from 1e-4 to 1e6", "[stability]") {
    far_coordinates_case(false);
}

TEST_CASE("kd-trees: accelerators agree with brute force at coordinates from 1e-4 to 1e6", "[stability]") {
    far_coordinates_case(true);
}
