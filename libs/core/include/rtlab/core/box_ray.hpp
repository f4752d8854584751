#pragma once
/// \brief The one ray/box slab test: AABB::intersect and every tree in accel use it, with the ray's inverse
/// direction and signs computed once.
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/core/ray.hpp>

#include <cmath>

namespace rtlab {

/// \brief Slab test against boxes with the inverse direction and its signs precomputed (Williams et al.
/// 2005). The near plane of each slab is picked by the sign bit, never by comparing distances. A zero
/// direction component gives an infinite inverse: outside its slab both distances share one sign (a miss),
/// inside they span everything, and for an origin on the slab's plane 0 * inf = NaN, which the comparisons
/// ignore (the axis then constrains nothing, which is exact there) -- for +0 and -0 alike. The far end and
/// the limit are enlarged by 2 gamma(3) (Ize 2013) so rounding never drops a hit.
struct BoxRay {
    float origin[3], inv[3];
    int negative[3];  ///< 1 for a negative direction component, -0 included
    float tmin;

    explicit BoxRay(const Ray& ray) : tmin(ray.tmin) {
        for (int a = 0; a < 3; ++a) {
            origin[a] = ray.origin[a];
            inv[a] = 1.0f / ray.direction[a];
            negative[a] = std::signbit(inv[a]) ? 1 : 0;
        }
    }
    /// t moved up by 2 gamma(3) relative; a product, so +-inf stays itself and never becomes NaN.
    static float enlarge(float t) {
        constexpr float kTwoGamma3 = 2.0f * gamma_bound(3);
        return t * (t > 0.0f ? 1.0f + kTwoGamma3 : 1.0f - kTwoGamma3);
    }
    /// The part [t0, t1] of [tmin, limit] inside box (t1 enlarged); false when the ray misses it.
    bool clip(const AABB& box, float limit, float& t0, float& t1) const {
        t0 = tmin;
        t1 = enlarge(limit);
        for (int a = 0; a < 3; ++a) {
            const float near_plane = negative[a] ? box.hi[a] : box.lo[a];
            const float far_plane = negative[a] ? box.lo[a] : box.hi[a];
            const float n = (near_plane - origin[a]) * inv[a];
            const float f = enlarge((far_plane - origin[a]) * inv[a]);
            t0 = n > t0 ? n : t0;  // false for NaN: keeps t0
            t1 = f < t1 ? f : t1;
        }
        return t0 <= t1;
    }
    /// Entry distance into box for t in [tmin, limit], or +inf when the ray misses it.
    float enter(const AABB& box, float limit) const {
        float t0, t1;
        return clip(box, limit, t0, t1) ? t0 : kInfinity;
    }
};

}  // namespace rtlab
