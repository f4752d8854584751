#include <rtlab/core/error.hpp>
#include <rtlab/shading/brdf.hpp>

#include "brdf_local.hpp"

#include <cmath>
#include <string>

namespace rtlab {

namespace {
bool same_hemisphere_above(const Vec3& wo, const Vec3& wi) { return wo.z > 0.0f && wi.z > 0.0f; }

void check_exponent(float e, const char* model) {
    if (!(e >= 0.0f) || !std::isfinite(e))
        throw Error(std::string(model) + ": exponent must be finite and >= 0, got " + std::to_string(e));
}
}  // namespace

RGB LambertBrdf::eval(const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere_above(wo, wi) ? m_albedo * kInvPi : RGB{};
}

float LambertBrdf::pdf(const Vec3& wo, const Vec3& wi) { return same_hemisphere_above(wo, wi) ? wi.z * kInvPi : 0.0f; }

std::optional<LobeDraw> LambertBrdf::sample(const Vec3& wo, const Vec2& u) {
    if (!(wo.z > 0.0f)) return std::nullopt;
    const Vec3 wi = sample_cosine_hemisphere(u);
    if (!(wi.z > 0.0f)) return std::nullopt;
    return LobeDraw{wi, kLobeDiffuse | kLobeReflection};
}

PhongBrdf::PhongBrdf(const RGB& kd, const RGB& ks, float exponent) : m_kd(kd), m_ks(ks), m_exponent(exponent) {
    check_exponent(exponent, "phong");
}

RGB PhongBrdf::eval(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere_above(wo, wi)) return {};
    const Vec3 mirror(-wo.x, -wo.y, wo.z);  // reflection of wo about +z
    // cos(alpha) = 1 - |mirror - wi|^2 / 2 for unit vectors.
    const Vec3 d = mirror - wi;
    const float lobe = (m_exponent + 2.0f) * (0.5f * kInvPi) * detail::pow_one_minus(0.5f * glm::dot(d, d), m_exponent);
    return m_kd * kInvPi + m_ks * lobe;
}

float PhongBrdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const float p_lobe = detail::specular_probability(channel_mean(m_kd), channel_mean(m_ks));
    if (!same_hemisphere_above(wo, wi) || p_lobe < 0.0f) return 0.0f;
    const Vec3 d = Vec3(-wo.x, -wo.y, wo.z) - wi;  // as in eval: 1 - cos(alpha) from the chord
    const float lobe = (m_exponent + 1.0f) * (0.5f * kInvPi) * detail::pow_one_minus(0.5f * glm::dot(d, d), m_exponent);
    return detail::two_part_pdf(p_lobe, wi.z, lobe);
}

std::optional<LobeDraw> PhongBrdf::sample(const Vec3& wo, float uc, const Vec2& u) const {
    const float p_lobe = detail::specular_probability(channel_mean(m_kd), channel_mean(m_ks));
    if (!(wo.z > 0.0f) || p_lobe < 0.0f) return std::nullopt;
    // A lobe reaching below the horizon loses those draws (absorbed).
    return detail::draw_two_part(p_lobe, uc, u, [&]() -> std::optional<Vec3> {
        return sample_power_cosine(Vec3(-wo.x, -wo.y, wo.z), m_exponent, u);
    });
}

BlinnPhongBrdf::BlinnPhongBrdf(const RGB& kd, const RGB& ks, float exponent)
    : m_kd(kd), m_ks(ks), m_exponent(exponent) {
    check_exponent(exponent, "blinn-phong");
    // At normal incidence (theta_i = 2 theta_h, d wi = 4 cos(theta_h) d h) the lobe's albedo is
    // 8 pi (e + 2^(-e/2)) / ((e + 2)(e + 4)) times its constant; c(e) makes that exactly 1.
    const double e = exponent;
    m_norm = static_cast<float>((e + 2.0) * (e + 4.0) / (8.0 * std::numbers::pi * (e + std::exp2(-0.5 * e))));
}

RGB BlinnPhongBrdf::eval(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere_above(wo, wi)) return {};
    const Vec3 h = detail::half_vector(wo, wi);
    // cos(theta_h)^e = (1 - sin^2)^(e / 2).
    const float lobe = m_norm * detail::pow_one_minus(h.x * h.x + h.y * h.y, 0.5f * m_exponent);
    return m_kd * kInvPi + m_ks * lobe;
}

}  // namespace rtlab

namespace rtlab {

float BlinnPhongBrdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const float p_lobe = detail::specular_probability(channel_mean(m_kd), channel_mean(m_ks));
    if (!same_hemisphere_above(wo, wi) || p_lobe < 0.0f) return 0.0f;
    const Vec3 h = detail::half_vector(wo, wi);
    const float pdf_h =
        (m_exponent + 1.0f) * (0.5f * kInvPi) * detail::pow_one_minus(h.x * h.x + h.y * h.y, 0.5f * m_exponent);
    const float wo_h = glm::dot(wo, h);
    const float lobe = wo_h > 0.0f ? pdf_h / (4.0f * wo_h) : 0.0f;
    return detail::two_part_pdf(p_lobe, wi.z, lobe);
}

std::optional<LobeDraw> BlinnPhongBrdf::sample(const Vec3& wo, float uc, const Vec2& u) const {
    const float p_lobe = detail::specular_probability(channel_mean(m_kd), channel_mean(m_ks));
    if (!(wo.z > 0.0f) || p_lobe < 0.0f) return std::nullopt;
    return detail::draw_two_part(p_lobe, uc, u, [&] {
        return detail::mirror_about(wo, sample_power_cosine(Vec3(0.0f, 0.0f, 1.0f), m_exponent, u));
    });
}

}  // namespace rtlab
