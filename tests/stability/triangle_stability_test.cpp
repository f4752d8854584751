// Ray-triangle tests where they are known to fail: rays aimed exactly at the shared edges and vertices of
// a tilted, irregular triangle grid (unbounded rays, and segments that end just past the target), at
// coordinates from 1e-4 to 1e6, and degenerate triangles. A leak is a ray through the inside of the grid
// that no triangle of the grid reports.
#include "record.hpp"

#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace rtlab;
using rtlab::stability::record;
using rtlab::stability::Row;

namespace {

/// An (n + 1) x (n + 1) vertex grid on a tilted plane, jittered inside the plane so no edge is axis-aligned
/// or regular; cell size `cell`, first corner at `offset`. Each cell is two triangles.
struct Grid {
    int n = 8;
    std::vector<Point3> vertices;
    std::vector<std::array<int, 3>> triangles;
    std::vector<std::pair<int, int>> interior_edges;  // shared by two triangles
    std::vector<int> interior_vertices;
    float extent = 0.0f;
    Point3 centre{0.0f};
};

Grid make_grid(float cell, const Point3& offset, std::uint32_t seed) {
    Grid g;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
    const Vec3 a = cell * glm::normalize(Vec3(1.0f, 0.31f, 0.17f));
    const Vec3 b = cell * glm::normalize(glm::cross(Vec3(0.2f, -0.45f, 1.0f), a / cell));
    const int n = g.n;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const bool border = i == 0 || j == 0 || i == n || j == n;
            const float di = border ? 0.0f : jitter(rng), dj = border ? 0.0f : jitter(rng);
            g.vertices.push_back(offset + (static_cast<float>(i) + di) * a + (static_cast<float>(j) + dj) * b);
            if (!border) g.interior_vertices.push_back(j * (n + 1) + i);
        }
    auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            g.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            g.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    // Interior edges: count how many triangles use each edge.
    std::map<std::pair<int, int>, int> uses;
    for (const auto& t : g.triangles)
        for (int k = 0; k < 3; ++k) {
            const int p = t[k], q = t[(k + 1) % 3];
            ++uses[{std::min(p, q), std::max(p, q)}];
        }
    for (const auto& [edge, count] : uses)
        if (count == 2) g.interior_edges.push_back(edge);
    g.extent = cell * static_cast<float>(n);
    g.centre = offset + 0.5f * static_cast<float>(n) * (a + b);
    return g;
}

/// Whether the watertight test's single-precision edge functions for this ray and triangle include an exact
/// zero, the case it recomputes in double (the same expressions as intersect_watertight).
bool watertight_falls_back(const WatertightRay& r, const Point3& p0, const Point3& p1, const Point3& p2) {
    const Vec3 a = p0 - r.origin, b = p1 - r.origin, c = p2 - r.origin;
    const float ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
    const float bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
    const float cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
    return cx * by - cy * bx == 0.0f || ax * cy - ay * cx == 0.0f || bx * ay - by * ax == 0.0f;
}

struct LeakCount {
    std::int64_t rays = 0, leaks = 0, fallbacks = 0;
};

enum class Target { edges, vertices };

/// Rays from random points around the grid (on both sides) to points on its interior edges (the float
/// lerp of the edge's ends, as a renderer would compute them) or exactly at its interior vertices. With
/// `bounded`, the ray ends 1e-5 of its length past the target.
LeakCount count_leaks(const Grid& g, TriangleTest test, Target target, bool bounded, int rays_per_target) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<PlaneTriangle> planes;
    for (const auto& t : g.triangles) planes.emplace_back(g.vertices[t[0]], g.vertices[t[1]], g.vertices[t[2]]);
    LeakCount count;
    auto shoot = [&](const Point3& to) {
        const float z = 2.0f * u(rng) - 1.0f, phi = 6.2831853f * u(rng);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const Point3 from = g.centre + 2.0f * g.extent * Vec3(r * std::cos(phi), r * std::sin(phi), z);
        const Vec3 d = to - from;
        const float len = glm::length(d);
        if (!(len > 0.0f)) return;
        const Vec3 dir = d / len;
        // The segment ends 1e-5 of its length past where it crosses the grid's plane (in double); grazing
        // segments, whose crossing moves by more than that when the target rounds off the plane, are skipped.
        const glm::dvec3 plane_n = glm::normalize(
            glm::cross(glm::dvec3(g.vertices[1] - g.vertices[0]), glm::dvec3(g.vertices[g.n + 1] - g.vertices[0])));
        const double cos_d = glm::dot(plane_n, glm::dvec3(dir));
        if (bounded && std::abs(cos_d) < 0.05) return;
        const double t_cross = glm::dot(plane_n, glm::dvec3(to) - glm::dvec3(from)) / cos_d;
        const Ray ray{from, dir, 0.0f, bounded ? static_cast<float>(t_cross * (1.0 + 1e-5)) : kInfinity};
        const WatertightRay wr(ray);
        bool hit = false;
        for (std::size_t i = 0; i < g.triangles.size(); ++i) {
            const Point3& p0 = g.vertices[g.triangles[i][0]];
            const Point3& p1 = g.vertices[g.triangles[i][1]];
            const Point3& p2 = g.vertices[g.triangles[i][2]];
            switch (test) {
                case TriangleTest::watertight:
                    count.fallbacks += watertight_falls_back(wr, p0, p1, p2);
                    hit |= intersect_watertight(wr, ray.tmin, ray.tmax, p0, p1, p2).has_value();
                    break;
                case TriangleTest::moller:
                    hit |= intersect_moller(ray, ray.tmin, ray.tmax, p0, p1, p2).has_value();
                    break;
                case TriangleTest::plane:
                    hit |= intersect_plane(ray, ray.tmin, ray.tmax, planes[i]).has_value();
                    break;
            }
        }
        ++count.rays;
        count.leaks += !hit;
    };
    for (int k = 0; k < rays_per_target; ++k) {
        if (target == Target::edges) {
            for (const auto& [p, q] : g.interior_edges) {
                // Away from the ends, whose rounding may move the target off the grid at its border.
                const float lambda = 0.02f + 0.96f * u(rng);
                shoot(g.vertices[p] + lambda * (g.vertices[q] - g.vertices[p]));
            }
        } else {
            for (int v : g.interior_vertices) shoot(g.vertices[v]);
        }
    }
    return count;
}

std::string scale_name(float s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", static_cast<double>(s));
    return buf;
}

void leak_rows(const std::string& where, float cell, const Point3& offset, int rays_per_target, bool with_bounded) {
    const Grid g = make_grid(cell, offset, 99);
    for (TriangleTest test : {TriangleTest::watertight, TriangleTest::moller, TriangleTest::plane}) {
        for (Target target : {Target::edges, Target::vertices}) {
            for (bool bounded : {false, true}) {
                if (bounded && !with_bounded) continue;
                const LeakCount c = count_leaks(g, test, target, bounded, rays_per_target);
                const std::string input = std::string(target == Target::edges ? "shared edges" : "shared vertices") +
                                          (bounded ? ", segment ending 1e-5 past (cos > 0.05)" : ", unbounded ray") +
                                          where;
                const bool promises = test == TriangleTest::watertight;
                record({"triangle test", std::string(to_string(test)), input, c.rays, c.leaks,
                        "leaks (no triangle hit)", std::nan(""), promises ? "0 leaks" : "none (measured only)"});
                if (test == TriangleTest::watertight)
                    record({"triangle test", "watertight double-precision fallback", input,
                            c.rays * static_cast<std::int64_t>(g.triangles.size()), c.fallbacks,
                            "ray-triangle tests recomputed in double", std::nan(""), "none (measured only)"});
                INFO(to_string(test) << " " << input << ": " << c.leaks << " leaks of " << c.rays);
                CHECK(c.rays > 0);
                if (promises) CHECK(c.leaks == 0);
            }
        }
    }
}

}  // namespace

TEST_CASE("triangle tests leak no ray through shared edges and vertices when watertight", "[stability]") {
    leak_rows("", 0.125f, Point3(-0.5f, -0.3f, 0.2f), 60, true);
}

TEST_CASE("triangle tests leak no ray at coordinates from 1e-4 to 1e6 when watertight", "[stability]") {
    for (float c : {1e-4f, 1e5f, 1e6f}) {
        // Cells of 1e-3 of the coordinate's size, so the triangles are still resolved in float.
        leak_rows(", coordinates ~" + scale_name(c), 1e-3f * c, Point3(c, 0.7f * c, -0.4f * c), 20, false);
    }
}

// The header promises that zero-area triangles are never hit: the watertight test (whose shear rounds
// collinear corners apart) and Moller-Trumbore once hit some; both now check a hit's corners exactly.
TEST_CASE("degenerate triangles are never hit by any triangle test", "[stability]") {
    // Zero-area triangles, exactly so in float (TriangleMesh::is_degenerate): repeated corners, corners on a
    // line through the origin at power-of-two steps, a corner in the middle of the opposite edge.
    const std::vector<std::array<Point3, 3>> tris = {
        {Point3(0, 0, 0), Point3(0, 0, 0), Point3(1, 1, 0)},
        {Point3(0, 0, 0), Point3(1, 1, 0), Point3(2, 2, 0)},
        {Point3(0, 0, 0), Point3(0.25f, 0.5f, 1.0f), Point3(0.5f, 1.0f, 2.0f)},
        {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0.5f, 0.0f, 0.0f)},
        {Point3(1, 1, 1), Point3(1, 1, 1), Point3(1, 1, 1)},
        {Point3(3, -1, 2), Point3(3, -1, 2), Point3(-5, 7, 0.5f)},
    };
    for (const auto& t : tris) {
        TriangleMesh m;
        m.positions = {t[0], t[1], t[2]};
        m.triangles = {{0u, 1u, 2u}};
        REQUIRE(m.is_degenerate(0));
    }
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), w(0.0f, 1.0f);
    for (TriangleTest test : {TriangleTest::watertight, TriangleTest::moller, TriangleTest::plane}) {
        std::int64_t tried = 0, hits = 0;
        for (const auto& t : tris) {
            const PlaneTriangle plane(t[0], t[1], t[2]);
            for (int k = 0; k < 4000; ++k) {
                // Aim at a point of the segment the triangle collapses to, from anywhere.
                const float a = w(rng);
                const Point3 target = (1.0f - a) * t[0] + a * (k % 2 ? t[1] : t[2]);
                const Point3 from = target + 3.0f * Vec3(u(rng), u(rng), u(rng));
                const Ray ray{from, target - from, 0.0f, kInfinity};
                bool hit = false;
                switch (test) {
                    case TriangleTest::watertight:
                        hit = intersect_watertight(WatertightRay(ray), 0.0f, kInfinity, t[0], t[1], t[2]).has_value();
                        break;
                    case TriangleTest::moller:
                        hit = intersect_moller(ray, 0.0f, kInfinity, t[0], t[1], t[2]).has_value();
                        break;
                    case TriangleTest::plane:
                        hit = intersect_plane(ray, 0.0f, kInfinity, plane).has_value();
                        break;
                }
                ++tried;
                hits += hit;
            }
        }
        record({"triangle test", std::string(to_string(test)), "degenerate triangles (repeated, collinear corners)",
                tried, hits, "hits reported on a zero-area triangle", std::nan(""), "0 hits"});
        INFO(to_string(test));
        CHECK(hits == 0);
    }
}
