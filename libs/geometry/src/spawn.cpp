#include <rtlab/geometry/spawn.hpp>

#include <cmath>

namespace rtlab {

Ray spawn_ray_to(const SurfaceHit& from, const SurfaceHit& to) {
    const Point3 origin = offset_ray_origin(from.point, from.point_error, from.geometric_normal, to.point - from.point);
    const Point3 end = offset_ray_origin(to.point, to.point_error, to.geometric_normal, origin - to.point);
    return Ray{origin, end - origin, 0.0f, 1.0f - kShadowEpsilon};
}

}  // namespace rtlab
