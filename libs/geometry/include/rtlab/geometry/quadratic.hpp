#pragma once
/// \brief The quadratic the round shapes (sphere, cylinder) solve, without cancellation.
#include <cmath>
#include <utility>

namespace rtlab::geometry {

/// Roots of a t^2 + 2 b t + c = 0 without catastrophic cancellation: the larger-magnitude root from
/// -(b + sign(b) sqrt(disc)), the other from c / q. `perp2` is the squared distance of the centre from the
/// ray's line times a (the discriminant a r^2 - |a oc - b d|^2 / a computed without subtracting two large
/// numbers, after Haines et al., Ray Tracing Gems ch. 7). Returns false when the line misses.
inline bool stable_roots(float a, float b, float c, float disc, float& t0, float& t1) {
    if (!(disc >= 0.0f) || !(a > 0.0f)) return false;
    const float q = -(b + std::copysign(std::sqrt(disc), b));
    if (q == 0.0f) {  // b = 0 and a tangent ray: one double root
        t0 = t1 = 0.0f;
        return c == 0.0f;
    }
    t0 = c / q;
    t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

}  // namespace rtlab::geometry
