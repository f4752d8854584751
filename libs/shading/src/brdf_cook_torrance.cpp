// Cook-Torrance: a Lambert base plus a specular microfacet lobe; see brdf.hpp for the formula.
#include <rtlab/shading/brdf.hpp>

#include "brdf_local.hpp"

namespace rtlab {

CookTorranceBrdf::CookTorranceBrdf(const RGB& kd, const RGB& ks, const MicrofacetDistribution& distribution,
                                   const Fresnel& fresnel)
    : m_kd(kd), m_ks(ks), m_distribution(distribution), m_fresnel(fresnel) {
    detail::check_colour(kd, "cook-torrance", "kd");
    detail::check_colour(ks, "cook-torrance", "ks");
}

RGB CookTorranceBrdf::eval(const Vec3& wo, const Vec3& wi) const {
    if (!detail::both_above(wo, wi)) return {};
    const Vec3 h = detail::half_vector(wo, wi);
    // The same for (wo, wi) and (wi, wo), bit for bit, so reciprocity does not depend on rounding.
    const float cos_d = std::min(1.0f, 0.5f * (glm::dot(wo, h) + glm::dot(wi, h)));
    // G1 / cos per direction keeps the 1 / (cos_o cos_i) finite at grazing angles; their product first, so
    // that swapping wo and wi cannot change the rounding.
    const float masking = m_distribution.g1_over_cos(wo) * m_distribution.g1_over_cos(wi);
    const float lobe = 0.25f * m_distribution.d(h) * masking;
    return m_kd * kInvPi + m_ks * m_fresnel.eval(cos_d) * lobe;
}

float CookTorranceBrdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const float p_lobe =
        detail::specular_probability(channel_mean(m_kd), channel_mean(m_ks * m_fresnel.eval(std::min(wo.z, 1.0f))));
    if (!detail::both_above(wo, wi) || p_lobe < 0.0f) return 0.0f;
    const Vec3 h = detail::half_vector(wo, wi);
    const float wo_h = glm::dot(wo, h);
    const float lobe = wo_h > 0.0f ? m_distribution.normal_pdf(wo, h) / (4.0f * wo_h) : 0.0f;
    return detail::two_part_pdf(p_lobe, wi.z, lobe);
}

std::optional<LobeDraw> CookTorranceBrdf::sample(const Vec3& wo, float uc, const Vec2& u) const {
    if (!(wo.z > 0.0f)) return std::nullopt;
    const float p_lobe =
        detail::specular_probability(channel_mean(m_kd), channel_mean(m_ks * m_fresnel.eval(std::min(wo.z, 1.0f))));
    if (p_lobe < 0.0f) return std::nullopt;
    return detail::draw_two_part(p_lobe, uc, u,
                                 [&] { return detail::mirror_about(wo, m_distribution.sample_normal(wo, u)); });
}

}  // namespace rtlab
