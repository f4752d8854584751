#pragma once
// Filling a SurfaceHit the same way for every analytic shape (private to the geometry library).
#include <rtlab/core/frame.hpp>
#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/quadratic.hpp>
#include <rtlab/geometry/surface_hit.hpp>

#include <cmath>

namespace rtlab::geometry {

/// point_error: per-axis bound on the distance of point from the true surface; outward: unit normal on the
/// side the shape calls outside; tangent_hint: dP/du, need not be unit or orthogonal (a zero hint, as at a
/// sphere's poles, falls back to an arbitrary tangent).
/// The unit tangent fill_hit() stores for a tangent hint and a unit normal.
inline Vec3 unit_tangent(const Vec3& tangent_hint, const Normal3& outward) {
    const Vec3 tangent = tangent_hint - glm::dot(tangent_hint, outward) * outward;
    const float len = glm::length(tangent);
    return len > 1e-12f && std::isfinite(len) ? tangent / len : Frame::from_normal(outward).s;
}

/// fill_hit() with the unit tangent already worked out (by unit_tangent(): a flat shape's is one for all hits).
inline void fill_hit_unit_tangent(SurfaceHit& hit, const Ray& ray, float t, const Point3& point,
                                  const Vec3& point_error, const Normal3& outward, Vec2 uv, const Vec3& tangent,
                                  std::uint32_t primitive, const Shape* shape) {
    hit.t = t;
    hit.point = point;
    hit.point_error = point_error;
    hit.object_point = point;
    hit.geometric_normal = outward;
    hit.shading_normal = outward;
    hit.uv = uv;
    hit.tangent = tangent;
    hit.primitive = primitive;
    hit.front_face = glm::dot(ray.direction, outward) < 0.0f;
    hit.shape = shape;
}

inline void fill_hit(SurfaceHit& hit, const Ray& ray, float t, const Point3& point, const Vec3& point_error,
                     const Normal3& outward, Vec2 uv, const Vec3& tangent_hint, std::uint32_t primitive,
                     const Shape* shape) {
    fill_hit_unit_tangent(hit, ray, t, point, point_error, outward, uv, unit_tangent(tangent_hint, outward), primitive,
                          shape);
}

/// Per-axis bound on the rounding of base + x s + y t + z n (a point given in a frame), plus the frame's own
/// departure from orthonormality, which the shape's intersection test sees when it goes back to the frame
/// (about gamma(3) each way); `local_error` is the bound on (x, y, z) themselves.
inline Vec3 frame_point_error(const Point3& world, const Frame& f, const Vec3& local, const Vec3& local_error) {
    const Vec3 as = glm::abs(f.s), at = glm::abs(f.t), an = glm::abs(f.n), al = glm::abs(local);
    return gamma_bound(8) * (al.x * as + al.y * at + al.z * an) + gamma_bound(2) * glm::abs(world) +
           local_error.x * as + local_error.y * at + local_error.z * an;
}

}  // namespace rtlab::geometry
