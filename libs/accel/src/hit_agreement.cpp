#include <rtlab/accel/hit_agreement.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

bool same_hit(bool hit_a, const MeshHit& a, bool hit_b, const MeshHit& b) {
    if (hit_a != hit_b) return false;
    if (!hit_a) return true;
    // In double: for any two float t, the difference and the tolerance are then exact enough and never
    // overflow or underflow.
    const double ta = a.t, tb = b.t;
    if (!std::isfinite(ta) || !std::isfinite(tb)) return ta == tb;
    return std::abs(ta - tb) <= kSameHitTolerance * std::max(std::abs(ta), std::abs(tb));
}

}  // namespace rtlab
