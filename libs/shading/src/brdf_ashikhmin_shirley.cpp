// Ashikhmin-Shirley anisotropic Phong: M. Ashikhmin and P. Shirley, "An anisotropic Phong BRDF model",
// Journal of Graphics Tools 5(2), 25-32, 2000, equations (4) and (5); see brdf.hpp for the formula.
#include <rtlab/shading/brdf.hpp>

#include "brdf_local.hpp"

#include <cmath>
#include <string>

namespace rtlab {

namespace {
float pow5(float x) { return (x * x) * (x * x) * x; }
}  // namespace

AshikhminShirleyBrdf::AshikhminShirleyBrdf(const RGB& rd, const RGB& rs, float nu, float nv)
    : m_rd(rd), m_rs(rs), m_nu(nu), m_nv(nv), m_specular_norm(std::sqrt((nu + 1.0f) * (nv + 1.0f)) / (8.0f * kPi)) {
    detail::check_colour(rd, "ashikhmin-shirley", "rd");
    detail::check_colour(rs, "ashikhmin-shirley", "rs");
    detail::check_parameter(nu >= 0.0f && std::isfinite(nu), "ashikhmin-shirley", "nu must be finite and >= 0", nu);
    detail::check_parameter(nv >= 0.0f && std::isfinite(nv), "ashikhmin-shirley", "nv must be finite and >= 0", nv);
}

RGB AshikhminShirleyBrdf::eval(const Vec3& wo, const Vec3& wi) const {
    if (!detail::both_above(wo, wi)) return {};
    const Vec3 h = detail::half_vector(wo, wi);
    const float cos_d = std::min(1.0f, 0.5f * (glm::dot(wo, h) + glm::dot(wi, h)));  // h.k, symmetric
    // (n.h)^p with p = (nu h_x^2 + nv h_y^2) / (1 - (n.h)^2), and 1 - (n.h)^2 = s2 = h_x^2 + h_y^2 for a
    // unit h; along the normal the power is 1.
    const float s2 = h.x * h.x + h.y * h.y;
    const float lobe = s2 > 0.0f ? detail::pow_one_minus(s2, 0.5f * (m_nu * h.x * h.x + m_nv * h.y * h.y) / s2) : 1.0f;
    // The paper's 1 / ((h.k) max(cos_o, cos_i)) has a pole where wo and wi reach the horizon from opposite
    // sides (h = n, h.k = cos_o = cos_i -> 0); the floor keeps eval finite there (cosines below 1e-15).
    constexpr float kMinDenominator = 1e-30f;
    const float specular = m_specular_norm * lobe / std::max(kMinDenominator, cos_d * std::max(wo.z, wi.z));
    const RGB fresnel = m_rs + (RGB(1.0f) - m_rs) * pow5(1.0f - cos_d);
    // The two falloffs multiplied first, so that swapping wo and wi cannot change the rounding.
    const float falloffs = (1.0f - pow5(1.0f - 0.5f * wo.z)) * (1.0f - pow5(1.0f - 0.5f * wi.z));
    const float diffuse = (28.0f / (23.0f * kPi)) * falloffs;
    return fresnel * specular + m_rd * (RGB(1.0f) - m_rs) * diffuse;
}

}  // namespace rtlab
