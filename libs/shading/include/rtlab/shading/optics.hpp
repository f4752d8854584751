#pragma once
/// \brief Reflection, refraction and Fresnel terms: the geometric optics of the Whitted recursion.
#include <rtlab/core/math.hpp>

#include <optional>

namespace rtlab {

/// Mirror direction of the incident direction `d` (pointing towards the surface) about unit normal n.
inline Vec3 reflect(const Vec3& d, const Normal3& n) { return d - 2.0f * glm::dot(d, n) * n; }

/// Refracted direction of unit incident direction `d` (pointing towards the surface) through a surface
/// with unit normal n facing the incident side, with eta = n_incident / n_transmitted.
/// nullopt on total internal reflection.
std::optional<Vec3> refract(const Vec3& d, const Normal3& n, float eta);

/// Unpolarised Fresnel reflectance of a dielectric interface; cos_i = cos of the incident angle (> 0 on the
/// side the light comes from), eta = n_incident / n_transmitted. 1 under total internal reflection.
float fresnel_dielectric(float cos_i, float eta);

/// Schlick's approximation of fresnel_dielectric, the fast variant charted against it.
float fresnel_schlick(float cos_i, float eta);

}  // namespace rtlab
