#pragma once
/// \brief A ray with its valid parameter range [tmin, tmax].
#include <rtlab/core/math.hpp>

namespace rtlab {

/// \brief origin + t * direction for t in [tmin, tmax]; the direction need not be normalised.
struct Ray {
    Point3 origin{0.0f};
    Vec3 direction{0.0f, 0.0f, 1.0f};
    float tmin = 0.0f;
    float tmax = kInfinity;

    Point3 at(float t) const { return origin + t * direction; }
};

}  // namespace rtlab
