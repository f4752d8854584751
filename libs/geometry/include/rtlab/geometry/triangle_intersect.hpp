#pragma once
/// \brief The three ray-triangle tests rtlab compares: watertight (default), Moller-Trumbore, plane + 2x2.
#include <rtlab/core/math.hpp>
#include <rtlab/core/ray.hpp>

#include <optional>
#include <string_view>

namespace rtlab {

/// Which ray-triangle test a mesh or accelerator uses.
enum class TriangleTest { watertight, moller, plane };

/// "watertight", "moller" or "plane"; throws rtlab::Error listing the valid names otherwise.
TriangleTest parse_triangle_test(std::string_view name);
std::string_view to_string(TriangleTest test);

/// \brief A ray-triangle hit: distance and barycentrics, point = (1-u-v) p0 + u p1 + v p2.
struct TriangleHit {
    float t;
    float u;
    float v;
};

/// \brief Per-ray precomputation of Woop, Benthin and Wald 2013 (axis permutation and shear).
struct WatertightRay {
    Point3 origin;
    int kx, ky, kz;
    float sx, sy, sz;
    explicit WatertightRay(const Ray& ray);
};

/// Watertight test (Woop et al. 2013): no ray through a shared edge or vertex of a closed mesh escapes.
std::optional<TriangleHit> intersect_watertight(const WatertightRay& ray, float tmin, float tmax, const Point3& p0,
                                                const Point3& p1, const Point3& p2);

/// Moller-Trumbore 1997: fast, but rays through edges and vertices can slip between triangles.
std::optional<TriangleHit> intersect_moller(const Ray& ray, float tmin, float tmax, const Point3& p0, const Point3& p1,
                                            const Point3& p2);

/// \brief The course's method, precomputed per triangle: the supporting plane, then alpha and beta from
/// the 2x2 system projected on the plane's dominant axis (the largest of the three 2x2 determinants).
struct PlaneTriangle {
    Normal3 normal;   ///< unnormalised plane normal (p1 - p0) x (p2 - p0)
    float offset;     ///< dot(normal, p0)
    Point3 p0;
    int ax, ay;       ///< the two axes kept by the projection
    float e1x, e1y, e2x, e2y;  ///< projected edges p1 - p0 and p2 - p0
    float inv_det;    ///< 1 / (e1x e2y - e1y e2x); 0 for a degenerate triangle
    PlaneTriangle() = default;
    PlaneTriangle(const Point3& p0, const Point3& p1, const Point3& p2);
};

std::optional<TriangleHit> intersect_plane(const Ray& ray, float tmin, float tmax, const PlaneTriangle& tri);

}  // namespace rtlab
