#include <rtlab/geometry/spawn.hpp>

#include <cmath>

namespace rtlab {

// pbrt-v4's method (Pharr, Jakob, Humphreys, 4th ed., 6.8.6) rather than Waechter and Binder 2019 (Ray
// Tracing Gems ch. 6): W&B move every point by a fixed 256 float steps of its own coordinates (and by a fixed
// 1/65536 near the origin) whatever the shape, so they cannot know when a point is less accurate than
// that (a triangle much larger than its hit point's coordinates, an instance's transform, a sphere far from
// its centre's scale) and they overshoot when it is more accurate (a box face, a quad at the origin),
// skipping a surface closer than their step. The bound each shape computes is the distance that matters.
Point3 offset_ray_origin(const Point3& p, const Vec3& p_error, const Normal3& ng, const Vec3& dir) {
    const float d = glm::dot(glm::abs(ng), p_error);
    const Normal3 side = glm::dot(dir, ng) < 0.0f ? -ng : ng;
    Point3 origin = p + d * side;
    // Rounding the sum may land back inside the bound: one more float step outwards on every axis the
    // normal leans along. Unlike pbrt, also when d = 0, so an exact point still leaves its surface.
    for (int a = 0; a < 3; ++a) {
        if (side[a] > 0.0f)
            origin[a] = next_float_up(origin[a]);
        else if (side[a] < 0.0f)
            origin[a] = next_float_down(origin[a]);
    }
    return origin;
}

Ray spawn_ray(const SurfaceHit& hit, const Vec3& dir) {
    return Ray{offset_ray_origin(hit.point, hit.point_error, hit.geometric_normal, dir), dir, 0.0f, kInfinity};
}

Ray spawn_ray_to(const SurfaceHit& hit, const Point3& target) {
    const Point3 origin = offset_ray_origin(hit.point, hit.point_error, hit.geometric_normal, target - hit.point);
    return Ray{origin, target - origin, 0.0f, 1.0f - kShadowEpsilon};
}

Ray spawn_ray_to(const SurfaceHit& from, const SurfaceHit& to) {
    const Point3 origin = offset_ray_origin(from.point, from.point_error, from.geometric_normal, to.point - from.point);
    const Point3 end = offset_ray_origin(to.point, to.point_error, to.geometric_normal, origin - to.point);
    return Ray{origin, end - origin, 0.0f, 1.0f - kShadowEpsilon};
}

}  // namespace rtlab
