#pragma once
/// \brief Orthonormal frame around a unit normal.
#include <rtlab/core/math.hpp>

namespace rtlab {

/// \brief Right-handed orthonormal basis (s, t, n) with n the given unit normal.
struct Frame {
    Vec3 s{1, 0, 0};
    Vec3 t{0, 1, 0};
    Vec3 n{0, 0, 1};

    /// Branchless construction of Duff et al. 2017 ("Building an Orthonormal Basis, Revisited"):
    /// continuous everywhere but at n.z = 0 crossing sign, and exact near n = (0, 0, -1), where the
    /// Frisvad original loses orthonormality.
    static Frame from_normal(const Normal3& n);

    Vec3 to_local(const Vec3& v) const { return {glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)}; }
    Vec3 to_world(const Vec3& v) const { return v.x * s + v.y * t + v.z * n; }
};

}  // namespace rtlab
