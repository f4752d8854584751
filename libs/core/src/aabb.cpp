#include <rtlab/core/aabb.hpp>

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
    if (is_empty() || !is_finite(ray.origin) || !is_finite(ray.direction)) return std::nullopt;
    float t0 = ray.tmin;
    float t1 = ray.tmax;
    if (!(t0 <= t1)) return std::nullopt;  // also rejects a NaN tmin or tmax
    constexpr float far_scale = 1.0f + 2.0f * gamma_bound(3);
    for (int a = 0; a < 3; ++a) {
        const float o = ray.origin[a];
        const float d = ray.direction[a];
        if (d == 0.0f) {  // +0 and -0: the ray runs inside the slab or never enters it
            if (o < lo[a] || o > hi[a]) return std::nullopt;
            continue;
        }
        // Division rather than multiplication by 1/d: a denormal d would make 1/d infinite and
        // (lo - o) * inf a NaN when the origin lies on the slab plane.
        float t_near = (lo[a] - o) / d;
        float t_far = (hi[a] - o) / d;
        if (t_near > t_far) std::swap(t_near, t_far);
        t_far *= far_scale;
        t0 = t_near > t0 ? t_near : t0;
        t1 = t_far < t1 ? t_far : t1;
        if (t0 > t1) return std::nullopt;
    }
    return Interval{t0, t1};
}

}  // namespace rtlab
