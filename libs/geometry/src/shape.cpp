#include <rtlab/geometry/shape.hpp>

namespace rtlab {

bool Shape::intersect_distance(const Ray& ray, float& t) const {
    SurfaceHit scratch;
    if (!intersect(ray, scratch)) return false;
    t = scratch.t;
    return true;
}

void Shape::complete_hit(const Ray& ray, float t, SurfaceHit& hit) const {
    // Only t itself passes (tmin, next float above t); the hit found at t before still does.
    Ray clamped = ray;
    clamped.tmax = next_float_up(t);
    intersect(clamped, hit);
}

std::optional<UvFootprint> Shape::uv_footprint(const Mat4&) const { return std::nullopt; }

}  // namespace rtlab
