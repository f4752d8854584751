#pragma once
// Small meshes the tests build themselves: an icosphere (closed), a grid of coplanar triangles, random
// soup, stacked quads. Shared by the geometry and accel tests.
#include <rtlab/geometry/triangle_mesh.hpp>

#include <cmath>
#include <map>
#include <random>
#include <utility>

namespace rtlab::test {

/// Closed unit icosphere: 20 * 4^subdivisions triangles, outward winding, shared vertices.
inline TriangleMesh icosphere(int subdivisions, float radius = 1.0f, Point3 centre = Point3(0.0f)) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    TriangleMesh m;
    for (const Vec3& v :
         {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0), Vec3(0, -1, t), Vec3(0, 1, t),
          Vec3(0, -1, -t), Vec3(0, 1, -t), Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)})
        m.positions.push_back(glm::normalize(v));
    m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
        auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            auto [it, inserted] = midpoint.try_emplace(key, static_cast<std::uint32_t>(m.positions.size()));
            if (inserted) m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
            return it->second;
        };
        std::vector<std::array<std::uint32_t, 3>> next;
        for (const auto& [a, b, c] : m.triangles) {
            const std::uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            next.push_back({a, ab, ca});
            next.push_back({b, bc, ab});
            next.push_back({c, ca, bc});
            next.push_back({ab, bc, ca});
        }
        m.triangles = std::move(next);
    }
    for (auto& p : m.positions) p = centre + radius * p;
    return m;
}

/// n x n unit squares in the plane z = z0, each split into two triangles: 2 n^2 coplanar triangles.
inline TriangleMesh coplanar_grid(int n, float z0 = 0.0f) {
    TriangleMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.positions.emplace_back(static_cast<float>(i), static_cast<float>(j), z0);
    auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return m;
}

/// Random triangles of size up to `size` in the cube [0, 10]^3.
inline TriangleMesh random_soup(int count, std::uint32_t seed, float size = 1.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    TriangleMesh m;
    for (int i = 0; i < count; ++i) {
        const Point3 base(10 * u(rng), 10 * u(rng), 10 * u(rng));
        for (int k = 0; k < 3; ++k)
            m.positions.push_back(base + size * Vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f));
        const auto b = static_cast<std::uint32_t>(3 * i);
        m.triangles.push_back({b, b + 1, b + 2});
    }
    return m;
}

/// `count` unit quads (two triangles each) all lying in the plane x = x0, shifted in y.
inline TriangleMesh stacked_quads(int count, float x0 = 1.0f) {
    TriangleMesh m;
    for (int i = 0; i < count; ++i) {
        const float y = 0.001f * static_cast<float>(i);
        const auto b = static_cast<std::uint32_t>(m.positions.size());
        m.positions.insert(m.positions.end(),
                           {Point3(x0, y, 0), Point3(x0, y + 1, 0), Point3(x0, y + 1, 1), Point3(x0, y, 1)});
        m.triangles.push_back({b, b + 1, b + 2});
        m.triangles.push_back({b, b + 2, b + 3});
    }
    return m;
}

}  // namespace rtlab::test

namespace rtlab::test {

/// Closed axis-aligned box [0, n]^3 whose six faces are n x n grids of unit squares split along a
/// diagonal: every vertex and every edge midpoint is exactly representable, the hardest case for
/// non-watertight tests (rays aimed exactly at shared edges).
inline TriangleMesh grid_box(int n) {
    TriangleMesh m;
    auto face = [&](int axis, float coordinate, bool flip) {
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                Point3 p(0.0f);
                p[axis] = coordinate;
                p[a1] = static_cast<float>(i);
                p[a2] = static_cast<float>(j);
                m.positions.push_back(p);
            }
        auto at = [&](int i, int j) { return base + static_cast<std::uint32_t>(j * (n + 1) + i); };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                std::array<std::uint32_t, 3> t1{at(i, j), at(i + 1, j), at(i + 1, j + 1)};
                std::array<std::uint32_t, 3> t2{at(i, j), at(i + 1, j + 1), at(i, j + 1)};
                if (flip) {
                    std::swap(t1[1], t1[2]);
                    std::swap(t2[1], t2[2]);
                }
                m.triangles.push_back(t1);
                m.triangles.push_back(t2);
            }
    };
    for (int axis = 0; axis < 3; ++axis) {
        face(axis, 0.0f, true);
        face(axis, static_cast<float>(n), false);
    }
    return m;
}

/// Squares of side `spacing` on every other cell of an n x n grid in the plane z = 0, centred on the origin, each
/// two triangles: every vertex belongs to one square only, so no neighbour catches a ray lost at a corner.
inline TriangleMesh isolated_squares(int n, float spacing) {
    TriangleMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            m.positions.emplace_back(static_cast<float>(i - n / 2) * spacing, static_cast<float>(j - n / 2) * spacing,
                                     0.0f);
    auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; j += 2)
        for (int i = 0; i < n; i += 2) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return m;
}

/// Unit cubes (side `scale`) in the cells of a 4 x 4 x 4 lattice whose coordinates add up to an even number,
/// from `offset`, each face two triangles: neighbours touch only at edges, every face lies in a lattice plane
/// shared by the faces of other cubes, and a kd-tree splits on those planes.
inline TriangleMesh cube_lattice(float scale, Point3 offset = Point3(0.0f)) {
    TriangleMesh m;
    auto quad = [&m](const Point3& o, const Vec3& a, const Vec3& b) {
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        m.positions.insert(m.positions.end(), {o, o + a, o + a + b, o + b});
        m.triangles.push_back({base, base + 1, base + 2});
        m.triangles.push_back({base, base + 2, base + 3});
    };
    const Vec3 x(scale, 0.0f, 0.0f), y(0.0f, scale, 0.0f), z(0.0f, 0.0f, scale);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) {
                if ((i + j + k) % 2) continue;
                const Point3 o =
                    offset + scale * Vec3(static_cast<float>(i), static_cast<float>(j), static_cast<float>(k));
                quad(o, y, x);
                quad(o + z, x, y);
                quad(o, x, z);
                quad(o + y, z, x);
                quad(o, z, y);
                quad(o + x, y, z);
            }
    return m;
}

}  // namespace rtlab::test
