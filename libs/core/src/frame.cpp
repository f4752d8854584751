#include <rtlab/core/frame.hpp>

#include <cmath>

namespace rtlab {

Frame Frame::from_normal(const Normal3& n) {
    // Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin: JCGT 6(1), 2017, listing 3.
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    Frame f;
    f.s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.t = Vec3(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

}  // namespace rtlab
