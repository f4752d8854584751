// Ashikhmin-Shirley anisotropic Phong: M. Ashikhmin and P. Shirley, "An anisotropic Phong BRDF model",
// Journal of Graphics Tools 5(2), 25-32, 2000, equations (4) and (5); see brdf.hpp for the formula.
#include <rtlab/shading/brdf.hpp>

#include "brdf_local.hpp"

#include <algorithm>
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

namespace {
// The share of the specular part: Schlick's F at cos_o against the diffuse part's (1 - rs) rd.
float as_specular_probability(const RGB& rd, const RGB& rs, float cos_o) {
    const RGB fresnel = rs + (RGB(1.0f) - rs) * pow5(1.0f - std::min(cos_o, 1.0f));
    return detail::specular_probability(channel_mean(rd * (RGB(1.0f) - rs)), channel_mean(fresnel));
}
// The paper's half-vector sampling: one quadrant of phi_h per quarter of u.x, mirrored into the other three.
Vec3 as_half_vector(float nu, float nv, const Vec2& u) {
    const float x = 4.0f * u.x;
    const int quadrant = std::min(3, static_cast<int>(x));
    const float v = x - static_cast<float>(quadrant);
    float phi = std::atan(std::sqrt((nu + 1.0f) / (nv + 1.0f)) * std::tan(0.5f * kPi * v));
    if (quadrant == 1) phi = kPi - phi;
    if (quadrant == 2) phi = kPi + phi;
    if (quadrant == 3) phi = 2.0f * kPi - phi;
    const float c = std::cos(phi), s = std::sin(phi);
    const float e = nu * c * c + nv * s * s;
    const float one_minus_cos = -std::expm1(std::log1p(-u.y) / (e + 1.0f));
    const float cos_h = 1.0f - one_minus_cos;
    const float sin_h = std::sqrt(std::max(0.0f, one_minus_cos * (1.0f + cos_h)));
    return glm::normalize(Vec3(sin_h * c, sin_h * s, cos_h));
}
}  // namespace

float AshikhminShirleyBrdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const float p_lobe = as_specular_probability(m_rd, m_rs, wo.z);
    if (!detail::both_above(wo, wi) || p_lobe < 0.0f) return 0.0f;
    const Vec3 h = detail::half_vector(wo, wi);
    const float s2 = h.x * h.x + h.y * h.y;
    const float power = s2 > 0.0f ? detail::pow_one_minus(s2, 0.5f * (m_nu * h.x * h.x + m_nv * h.y * h.y) / s2) : 1.0f;
    const float pdf_h = 4.0f * m_specular_norm * power;  // sqrt((nu + 1)(nv + 1)) / (2 pi) (n.h)^(...)
    const float wo_h = glm::dot(wo, h);
    const float lobe = wo_h > 0.0f ? pdf_h / (4.0f * wo_h) : 0.0f;
    return detail::two_part_pdf(p_lobe, wi.z, lobe);
}

std::optional<LobeDraw> AshikhminShirleyBrdf::sample(const Vec3& wo, float uc, const Vec2& u) const {
    const float p_lobe = as_specular_probability(m_rd, m_rs, wo.z);
    if (!(wo.z > 0.0f) || p_lobe < 0.0f) return std::nullopt;
    return detail::draw_two_part(p_lobe, uc, u,
                                 [&] { return detail::mirror_about(wo, as_half_vector(m_nu, m_nv, u)); });
}

}  // namespace rtlab
