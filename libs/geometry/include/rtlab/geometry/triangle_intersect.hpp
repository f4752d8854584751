#pragma once
/// \brief The three ray-triangle tests rtlab compares: watertight (default), Moller-Trumbore, plane + 2x2.
///
/// All three accept hits with tmin < t < tmax and report barycentrics (u, v) with
/// point = (1-u-v) p0 + u p1 + v p2. They are defined inline: they are the innermost loop of every
/// accelerator. Degenerate triangles (zero area) are never hit.
#include <rtlab/core/math.hpp>
#include <rtlab/core/ray.hpp>

#include <cmath>
#include <optional>
#include <string_view>

namespace rtlab {

/// Whether the corners are collinear (or one is not finite): in double, the cross product of the float edges
/// is exact enough that zero means collinear corners, not a small triangle lost to rounding. Such a triangle
/// has no plane and no normal, so no test reports a hit on it; meshes drop them when their trees are built.
inline bool is_degenerate_triangle(const Point3& a, const Point3& b, const Point3& c) {
    if (!is_finite(a) || !is_finite(b) || !is_finite(c)) return true;
    const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a);
    const glm::dvec3 e2 = glm::dvec3(c) - glm::dvec3(a);
    const glm::dvec3 n = glm::cross(e1, e2);
    return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}

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

/// \brief Per-ray precomputation of Woop, Benthin and Wald 2013: the axis kz of the largest direction
/// component, the other two permuted to keep the winding, and the shear that maps the ray to +z.
struct WatertightRay {
    Point3 origin;
    int kx = 0, ky = 1, kz = 2;
    float sx = 0.0f, sy = 0.0f, sz = 1.0f;
    bool valid = false;  ///< false for a zero or non-finite direction or origin: such rays hit nothing

    explicit WatertightRay(const Ray& ray);
};

/// \brief A conservative bound on the rounding error of the watertight test's t, after pbrt-v4 (4th ed.,
/// 6.8.7), from the largest magnitudes over the three vertices of: the sheared ray-space x and y, the
/// unscaled z (a[kz], world units like x and y), the z scaled by sz (t units), the edge functions, and
/// |1 / det|.
///
/// A hit with t no larger than it may be the ray's own origin surface seen again through rounding: a ray
/// spawned off a triangle by its point error bound otherwise re-hits that triangle now and then (11 to 20 of
/// 200,000 from large triangles around the world's origin, tests/geometry/triangle_t_error_test.cpp). pbrt
/// bounds the error of x and y with the scaled z, which is right only for
/// unit directions; here the z that was multiplied by the shear is the unscaled one, so the bound stays a
/// few ulps of t for a direction of any length. A template so that accel's packet kernel evaluates the same
/// expression on its lanes (T = a GCC vector) and rejects exactly what this test rejects.
template <class T>
inline T watertight_t_error(T max_x, T max_y, T max_z_world, T max_z, T max_e, T abs_inv_det) {
    const T delta_z = gamma_bound(3) * max_z;
    const T delta_x = gamma_bound(5) * (max_x + max_z_world);
    const T delta_y = gamma_bound(5) * (max_y + max_z_world);
    const T delta_e = 2.0f * (gamma_bound(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    return 3.0f * (gamma_bound(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * abs_inv_det;
}

/// \brief Whether a hit whose float t is within watertight_t_error is really in front of the origin: t again
/// in double precision from the same vertices and shear, accepted when it exceeds the same bound with
/// double's epsilon (about 2^-29 of the float one).
///
/// The float bound is conservative by orders of magnitude: alone it also rejects true hits a little way off
/// (an inward ray spawned near a cube's edge, whose adjacent face is 4.8e-5 away against a bound of 5.0e-5,
/// escaped the solid). Only hits within the float bound come here, so it costs nothing on ordinary hits.
bool watertight_near_hit_in_front(const WatertightRay& r, const Point3& p0, const Point3& p1, const Point3& p2);

/// The largest of |a|, |b|, |c|.
inline float max_abs3(float a, float b, float c) {
    return std::fmax(std::fabs(a), std::fmax(std::fabs(b), std::fabs(c)));
}

/// Watertight test (Woop et al. 2013): a ray through a shared edge or vertex of a closed mesh hits at
/// least one of the triangles there, never none. Edge functions that round to exactly zero are
/// recomputed in double precision, as the paper prescribes.
inline std::optional<TriangleHit> intersect_watertight(const WatertightRay& r, float tmin, float tmax, const Point3& p0,
                                                       const Point3& p1, const Point3& p2) {
    if (!r.valid) return std::nullopt;
    const Vec3 a = p0 - r.origin, b = p1 - r.origin, c = p2 - r.origin;
    const float ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
    const float bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
    const float cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = static_cast<float>(static_cast<double>(cx) * by - static_cast<double>(cy) * bx);
        v = static_cast<float>(static_cast<double>(ax) * cy - static_cast<double>(ay) * cx);
        w = static_cast<float>(static_cast<double>(bx) * ay - static_cast<double>(by) * ax);
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return std::nullopt;
    const float det = u + v + w;
    if (det == 0.0f || !std::isfinite(det)) return std::nullopt;
    const float az = r.sz * a[r.kz], bz = r.sz * b[r.kz], cz = r.sz * c[r.kz];
    const float t_scaled = u * az + v * bz + w * cz;
    // Compare t * det against the range before dividing (the sign of det flips the comparison).
    if (det > 0.0f ? !(t_scaled > tmin * det && t_scaled < tmax * det)
                   : !(t_scaled < tmin * det && t_scaled > tmax * det))
        return std::nullopt;
    const float inv = 1.0f / det;
    const float t = t_scaled * inv;
    if (!(t > tmin && t < tmax)) return std::nullopt;  // tmax = inf makes tmax * det an inf or NaN above
    if (t <= watertight_t_error(max_abs3(ax, bx, cx), max_abs3(ay, by, cy), max_abs3(a[r.kz], b[r.kz], c[r.kz]),
                                max_abs3(az, bz, cz), max_abs3(u, v, w), std::fabs(inv)) &&
        !watertight_near_hit_in_front(r, p0, p1, p2))
        return std::nullopt;
    // Checked only for hits, where it costs little: the shear can round collinear corners apart.
    if (is_degenerate_triangle(p0, p1, p2)) return std::nullopt;
    return TriangleHit{t, v * inv, w * inv};
}

/// Moller-Trumbore 1997: fast, but rays through edges and vertices can slip between triangles.
inline std::optional<TriangleHit> intersect_moller(const Ray& ray, float tmin, float tmax, const Point3& p0,
                                                   const Point3& p1, const Point3& p2) {
    const Vec3 e1 = p1 - p0, e2 = p2 - p0;
    const Vec3 pvec = glm::cross(ray.direction, e2);
    const float det = glm::dot(e1, pvec);
    if (det == 0.0f || !std::isfinite(det)) return std::nullopt;
    const float inv = 1.0f / det;
    const Vec3 tvec = ray.origin - p0;
    const float u = glm::dot(tvec, pvec) * inv;
    if (!(u >= 0.0f && u <= 1.0f)) return std::nullopt;
    const Vec3 qvec = glm::cross(tvec, e1);
    const float v = glm::dot(ray.direction, qvec) * inv;
    if (!(v >= 0.0f && u + v <= 1.0f)) return std::nullopt;
    const float t = glm::dot(e2, qvec) * inv;
    if (!(t > tmin && t < tmax)) return std::nullopt;
    if (is_degenerate_triangle(p0, p1, p2)) return std::nullopt;  // only for hits: rounding can make det != 0
    return TriangleHit{t, u, v};
}

/// \brief The course's method, precomputed per triangle: the supporting plane, then alpha and beta from
/// the 2x2 system projected on the plane's dominant axis (the largest of the three 2x2 determinants).
struct PlaneTriangle {
    Normal3 normal{0.0f};  ///< unnormalised plane normal (p1 - p0) x (p2 - p0)
    float offset = 0.0f;   ///< dot(normal, p0)
    float p0x = 0.0f, p0y = 0.0f;
    int ax = 0, ay = 1;                                    ///< the two axes kept by the projection
    float e1x = 0.0f, e1y = 0.0f, e2x = 0.0f, e2y = 0.0f;  ///< projected edges p1 - p0 and p2 - p0
    float inv_det = 0.0f;  ///< 1 / (e1x e2y - e1y e2x); 0 marks a degenerate triangle (never hit)

    PlaneTriangle() = default;
    PlaneTriangle(const Point3& p0, const Point3& p1, const Point3& p2);
};

inline std::optional<TriangleHit> intersect_plane(const Ray& ray, float tmin, float tmax, const PlaneTriangle& tri) {
    if (tri.inv_det == 0.0f) return std::nullopt;
    const float denom = glm::dot(tri.normal, ray.direction);
    if (denom == 0.0f) return std::nullopt;  // parallel to the plane
    const float t = (tri.offset - glm::dot(tri.normal, ray.origin)) / denom;
    if (!(t > tmin && t < tmax)) return std::nullopt;
    const float px = ray.origin[tri.ax] + t * ray.direction[tri.ax] - tri.p0x;
    const float py = ray.origin[tri.ay] + t * ray.direction[tri.ay] - tri.p0y;
    const float alpha = (px * tri.e2y - py * tri.e2x) * tri.inv_det;
    const float beta = (tri.e1x * py - tri.e1y * px) * tri.inv_det;
    if (!(alpha >= 0.0f && beta >= 0.0f && alpha + beta <= 1.0f)) return std::nullopt;
    return TriangleHit{t, alpha, beta};
}

}  // namespace rtlab
