#include <rtlab/core/aabb.hpp>
#include <rtlab/core/box_ray.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

float AABB::surface_area() const {
    if (is_empty()) return 0.0f;
    const Vec3 d = extent();
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

bool AABB::contains(const Point3& p) const {
    return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
}

std::optional<Interval> AABB::intersect(const Ray& ray) const {
    // BoxRay ignores a NaN distance, so a NaN or infinite ray must be refused before it gets there.
    if (is_empty() || !is_finite(ray.origin) || !is_finite(ray.direction)) return std::nullopt;
    if (!(ray.tmin <= ray.tmax)) return std::nullopt;  // also rejects a NaN tmin or tmax
    float t0 = 0.0f, t1 = 0.0f;
    if (!BoxRay(ray).clip(*this, ray.tmax, t0, t1)) return std::nullopt;
    // clip enlarges its limit for conservative tree traversal; this range ends at tmax. A zero direction
    // component outside its slab gives an entry at +inf or an exit at -inf, which clip accepts only when
    // nothing finite bounds the range (a zero direction, or tmin = -inf): still a miss.
    if (t0 > ray.tmax || t0 == kInfinity || t1 == -kInfinity) return std::nullopt;
    return Interval{t0, std::min(t1, ray.tmax)};
}

}  // namespace rtlab
