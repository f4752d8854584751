#pragma once
/// \brief Secondary rays leaving a surface hit: reflection, refraction, shadow and connection rays that never
/// hit their own surface again and never skip a nearby one.
///
/// The origin is moved off the surface by the hit's own error bound (SurfaceHit::point_error) along the
/// geometric normal, to the side the new ray leaves: never by a fixed epsilon, which is too small for a
/// point far from the world's origin and too large for a small or nearby shape. The one routine shading,
/// render and rtlab-accel share.
#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/surface_hit.hpp>

#include <bit>
#include <cstdint>

namespace rtlab {

/// Shadow and connection rays end at t = 1 - kShadowEpsilon of their segment (pbrt-v4's ShadowEpsilon), so
/// the target's own surface, or a light sample on it, does not block the ray that reaches it. Relative to
/// the segment: an occluder within 1e-4 of the distance from the target is not seen.
inline constexpr float kShadowEpsilon = 1e-4f;

/// p moved off its surface by the error bound p_error projected on the unit geometric normal ng, to the
/// side of the surface that dir leaves (ng's side when dot(dir, ng) >= 0), then each moved component one
/// float step further (so a point with a zero bound still leaves the surface by one step).
/// Inline, with the two spawns below: the Whitted recursion spawns a ray or two at every hit.
inline Point3 offset_ray_origin(const Point3& p, const Vec3& p_error, const Normal3& ng, const Vec3& dir);

/// A ray leaving the hit along dir (not normalised): the origin offset towards dir's side, tmin 0, tmax inf.
inline Ray spawn_ray(const SurfaceHit& hit, const Vec3& dir);

/// A shadow ray from the hit to a point not on a surface (a point light): direction = target - origin,
/// tmin 0, tmax 1 - kShadowEpsilon, so t in (0, 1) spans the segment.
inline Ray spawn_ray_to(const SurfaceHit& hit, const Point3& target);

/// A shadow or connection ray between two surface hits (a point and a light sample on an area light):
/// both ends offset off their surfaces towards each other; direction = end - origin, tmax 1 - kShadowEpsilon.
Ray spawn_ray_to(const SurfaceHit& from, const SurfaceHit& to);

/// next_float_up (std::nextafter(x, +inf)) in one compare: NaN and +inf stay, and x + 0 turns -0 into +0 (and
/// leaves every other float as it is), which then steps like +0. Every spawned ray takes up to three.
inline float spawn_step_up(float x) {
    if (!(x < kInfinity)) return x;
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(x + 0.0f);
    // Sign-magnitude: away from zero above it, towards zero below (-inf to -max).
    return std::bit_cast<float>(bits >> 31 ? bits - 1 : bits + 1);
}

// pbrt-v4's method (Pharr, Jakob, Humphreys, 4th ed., 6.8.6) rather than Waechter and Binder 2019 (Ray
// Tracing Gems ch. 6): W&B move every point by a fixed 256 float steps of its own coordinates (and by a fixed
// 1/65536 near the origin) whatever the shape, so they cannot know when a point is less accurate than
// that (a triangle much larger than its hit point's coordinates, an instance's transform, a sphere far from
// its centre's scale) and they overshoot when it is more accurate (a box face, a quad at the origin),
// skipping a surface closer than their step. The bound each shape computes is the distance that matters.
inline Point3 offset_ray_origin(const Point3& p, const Vec3& p_error, const Normal3& ng, const Vec3& dir) {
    const float d = glm::dot(glm::abs(ng), p_error);
    const Normal3 side = glm::dot(dir, ng) < 0.0f ? -ng : ng;
    Point3 origin = p + d * side;
    // Rounding the sum may land back inside the bound: one more float step outwards on every axis the
    // normal leans along. Unlike pbrt, also when d = 0, so an exact point still leaves its surface.
    for (int a = 0; a < 3; ++a) {
        if (side[a] > 0.0f)
            origin[a] = spawn_step_up(origin[a]);
        else if (side[a] < 0.0f)
            origin[a] = -spawn_step_up(-origin[a]);
    }
    return origin;
}

inline Ray spawn_ray(const SurfaceHit& hit, const Vec3& dir) {
    return Ray{offset_ray_origin(hit.point, hit.point_error, hit.geometric_normal, dir), dir, 0.0f, kInfinity};
}

inline Ray spawn_ray_to(const SurfaceHit& hit, const Point3& target) {
    const Point3 origin = offset_ray_origin(hit.point, hit.point_error, hit.geometric_normal, target - hit.point);
    return Ray{origin, target - origin, 0.0f, 1.0f - kShadowEpsilon};
}

}  // namespace rtlab
