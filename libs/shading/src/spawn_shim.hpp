#pragma once
// TEMPORARY stand-in for rtlab/geometry/spawn.hpp and SurfaceHit::object_point (branch `spawn`); goes when
// that lands. Offsets by Waechter and Binder's (Ray Tracing Gems, ch. 6) integer-ulp rule along the
// geometric normal, on the side the new ray leaves; shadow rays to a point stop at 1 - 1e-4.
#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/surface_hit.hpp>

#include <bit>
#include <cmath>
#include <cstdint>

namespace rtlab::shading_detail {

inline Point3 offset_origin(const SurfaceHit& hit, const Vec3& dir) {
    constexpr float kOrigin = 1.0f / 32.0f, kFloatScale = 1.0f / 65536.0f, kIntScale = 256.0f;
    const Vec3 n = glm::dot(dir, hit.geometric_normal) < 0.0f ? -hit.geometric_normal : hit.geometric_normal;
    Point3 out;
    for (int i = 0; i < 3; ++i) {
        const float p = hit.point[i];
        const auto of = static_cast<std::int32_t>(kIntScale * n[i]);
        const float pi = std::bit_cast<float>(std::bit_cast<std::int32_t>(p) + (p < 0.0f ? -of : of));
        out[i] = std::abs(p) < kOrigin ? p + kFloatScale * n[i] : pi;
    }
    return out;
}

inline Ray spawn_ray(const SurfaceHit& hit, const Vec3& dir) {
    return Ray{offset_origin(hit, dir), dir, 0.0f, kInfinity};
}

inline Ray spawn_ray_to(const SurfaceHit& hit, const Point3& target) {
    const Point3 o = offset_origin(hit, target - hit.point);
    return Ray{o, target - o, 0.0f, 1.0f - 1e-4f};
}

inline Point3 object_point(const SurfaceHit& hit) { return hit.point; }

}  // namespace rtlab::shading_detail
