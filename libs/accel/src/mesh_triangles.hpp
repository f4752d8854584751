#pragma once
// A mesh's triangles laid out for one triangle test, and the per-triangle test every accelerator's
// leaves call (private to the accel library).
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/core/box_ray.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace rtlab::accel {

/// \brief Corners (watertight, moller) or plane data (plane) of a mesh's triangles, each entry holding
/// triangle order[k] (all triangles in mesh order when no order is given). Accelerators pass their
/// leaves' order so that a leaf's triangles sit next to each other in memory: incoherent rays then pay
/// one cache miss per leaf, not one per triangle. Degenerate triangles are marked unusable.
class MeshTriangles {
public:
    MeshTriangles(const TriangleMesh& mesh, TriangleTest test, std::vector<std::uint32_t> order = {})
        : m_test(test), m_original(std::move(order)) {
        if (m_original.empty()) {
            m_original.resize(mesh.triangle_count());
            for (std::size_t i = 0; i < m_original.size(); ++i) m_original[i] = static_cast<std::uint32_t>(i);
        }
        const std::size_t n = m_original.size();
        m_usable.resize(n);
        if (test == TriangleTest::plane)
            m_planes.resize(n);
        else
            m_corners.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t i = m_original[k];
            m_usable[k] = !mesh.is_degenerate(i);
            if (test == TriangleTest::plane)
                m_planes[k] = PlaneTriangle(mesh.corner(i, 0), mesh.corner(i, 1), mesh.corner(i, 2));
            else
                m_corners[k] = {mesh.corner(i, 0), mesh.corner(i, 1), mesh.corner(i, 2)};
        }
    }

    TriangleTest test() const { return m_test; }
    std::size_t size() const { return m_usable.size(); }
    bool usable(std::size_t k) const { return m_usable[k] != 0; }
    /// The mesh's index of entry k.
    std::uint32_t original(std::size_t k) const { return m_original[k]; }
    std::size_t bytes() const {
        return m_corners.size() * sizeof(m_corners[0]) + m_planes.size() * sizeof(PlaneTriangle) + m_usable.size() +
               m_original.size() * sizeof(std::uint32_t);
    }
    const std::array<Point3, 3>& corners(std::uint32_t k) const { return m_corners[k]; }
    const PlaneTriangle& plane(std::uint32_t k) const { return m_planes[k]; }

private:
    TriangleTest m_test;
    std::vector<std::uint32_t> m_original;
    std::vector<std::array<Point3, 3>> m_corners;
    std::vector<PlaneTriangle> m_planes;
    std::vector<std::uint8_t> m_usable;
};

/// \brief Per-ray data of a triangle test: the watertight shear, or nothing.
template <TriangleTest Test>
struct TriangleRay {
    const Ray& ray;
    explicit TriangleRay(const Ray& r) : ray(r) {}
};
template <>
struct TriangleRay<TriangleTest::watertight> {
    const Ray& ray;
    WatertightRay sheared;
    explicit TriangleRay(const Ray& r) : ray(r), sheared(r) {}
};

/// Tests entry i for tmin < t < closest; on a hit fills hit (with the mesh's triangle index) and lowers closest.
template <TriangleTest Test>
inline bool test_triangle(const MeshTriangles& tris, const TriangleRay<Test>& r, std::uint32_t i, float& closest,
                          MeshHit& hit) {
    std::optional<TriangleHit> h;
    if constexpr (Test == TriangleTest::watertight) {
        const auto& c = tris.corners(i);
        h = intersect_watertight(r.sheared, r.ray.tmin, closest, c[0], c[1], c[2]);
    } else if constexpr (Test == TriangleTest::moller) {
        const auto& c = tris.corners(i);
        h = intersect_moller(r.ray, r.ray.tmin, closest, c[0], c[1], c[2]);
    } else {
        h = intersect_plane(r.ray, r.ray.tmin, closest, tris.plane(i));
    }
    if (!h) return false;
    closest = h->t;
    hit = MeshHit{h->t, tris.original(i), h->u, h->v};
    return true;
}

/// Tests the leaf entries [first, first + count): true on a hit; with AnyHit it stops at the first one.
template <TriangleTest Test, bool AnyHit>
inline bool test_leaf(const MeshTriangles& tris, const TriangleRay<Test>& r, std::uint32_t first, std::uint32_t count,
                      float& closest, MeshHit& hit) {
    bool any = false;
    for (std::uint32_t k = 0; k < count; ++k) {
        if (test_triangle<Test>(tris, r, first + k, closest, hit)) {
            any = true;
            if constexpr (AnyHit) return true;
        }
    }
    return any;
}

/// Calls f.template operator()<Test>() for the runtime test: one switch per query, not per triangle.
template <class F>
decltype(auto) dispatch_triangle_test(TriangleTest test, F&& f) {
    switch (test) {
        case TriangleTest::moller:
            return f.template operator()<TriangleTest::moller>();
        case TriangleTest::plane:
            return f.template operator()<TriangleTest::plane>();
        case TriangleTest::watertight:
            break;
    }
    return f.template operator()<TriangleTest::watertight>();
}

/// False for a ray no structure can hit: a NaN anywhere, or an empty interval.
inline bool usable_ray(const Ray& ray) {
    for (int a = 0; a < 3; ++a)
        if (std::isnan(ray.origin[a]) || std::isnan(ray.direction[a])) return false;
    return !std::isnan(ray.tmin) && !std::isnan(ray.tmax) && ray.tmin < ray.tmax;
}

/// Bounds of the part of triangle (a, b, c) inside box (Sutherland-Hodgman clipping), empty if none.
AABB clip_triangle(const Point3& a, const Point3& b, const Point3& c, const AABB& box);

}  // namespace rtlab::accel
