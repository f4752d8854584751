// The rough dielectric of Walter et al. 2007; see rough_dielectric.hpp for the formulas.
#include <rtlab/shading/optics.hpp>
#include <rtlab/shading/rough_dielectric.hpp>

#include "brdf_local.hpp"

#include <cmath>

namespace rtlab {

namespace {
// The masking function is defined for directions above the microsurface's mean plane; from below the
// interface is the same surface seen upside down.
Vec3 upper(const Vec3& v) { return {v.x, v.y, std::abs(v.z)}; }
}  // namespace

RoughDielectricBsdf::RoughDielectricBsdf(const MicrofacetDistribution& distribution, float eta)
    : m_distribution(distribution), m_eta(eta) {
    detail::check_parameter(eta > 0.0f && std::isfinite(eta), "rough dielectric", "eta must be finite and > 0", eta);
}

std::optional<RoughDielectricBsdf::Pair> RoughDielectricBsdf::pair(const Vec3& wo, const Vec3& wi) const {
    if (wo.z == 0.0f || wi.z == 0.0f) return std::nullopt;
    Pair p;
    p.reflect = wo.z * wi.z > 0.0f;
    p.n_o = index(wo.z);
    p.n_i = p.reflect ? p.n_o : index(wi.z);
    Vec3 m = p.reflect ? wo + wi : p.n_o * wo + p.n_i * wi;
    const float len2 = glm::dot(m, m);
    if (!(len2 > 0.0f)) return std::nullopt;
    m /= std::sqrt(len2);
    if (m.z < 0.0f) m = -m;
    // A microfacet seen from its back by either direction takes no part.
    if (!(glm::dot(wo, m) * wo.z > 0.0f) || !(glm::dot(wi, m) * wi.z > 0.0f)) return std::nullopt;
    p.m = m;
    // The same reflectance from either side of a refraction pair, worked out from the optically thinner one,
    // where no cosine sits near the critical angle: swapping wo and wi then gives the same number bit for
    // bit, and the generalised reciprocity holds to rounding.
    const Vec3& thin = p.reflect || p.n_o <= p.n_i ? wo : wi;
    p.fresnel = fresnel_dielectric(std::abs(glm::dot(thin, m)), index(thin.z) / index(-thin.z));
    return p;
}

float RoughDielectricBsdf::eval(const Vec3& wo, const Vec3& wi, TransportMode mode) const {
    const std::optional<Pair> p = pair(wo, wi);
    if (!p) return 0.0f;
    const float d = m_distribution.d(p->m);
    // G1 / cos per direction keeps grazing directions finite (both vanish together).
    const float masking = m_distribution.g1_over_cos(upper(wo)) * m_distribution.g1_over_cos(upper(wi));
    if (p->reflect) return 0.25f * p->fresnel * d * masking;
    const float wo_m = glm::dot(wo, p->m), wi_m = glm::dot(wi, p->m);
    const float denom = p->n_i * wi_m + p->n_o * wo_m;
    const float n = mode == TransportMode::radiance ? p->n_o : p->n_i;
    return std::abs(wo_m * wi_m) * (1.0f - p->fresnel) * d * masking * (n * n) / (denom * denom);
}

float RoughDielectricBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const std::optional<Pair> p = pair(wo, wi);
    if (!p) return 0.0f;
    // The normals were drawn for the viewer turned to the upper side (the whole vector, as the microsurface
    // seen from below is the same surface).
    const Vec3 view = wo.z > 0.0f ? wo : -wo;
    const float pdf_m = m_distribution.normal_pdf(view, p->m);
    const float wo_m = glm::dot(wo, p->m);
    if (p->reflect) return p->fresnel * pdf_m / (4.0f * std::abs(wo_m));
    const float wi_m = glm::dot(wi, p->m);
    const float denom = p->n_i * wi_m + p->n_o * wo_m;
    // d m / d wi for refraction: n_i^2 |wi.m| / (n_i (wi.m) + n_o (wo.m))^2.
    return (1.0f - p->fresnel) * pdf_m * p->n_i * p->n_i * std::abs(wi_m) / (denom * denom);
}

std::optional<LobeDraw> RoughDielectricBsdf::sample(const Vec3& wo, float uc, const Vec2& u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float side = wo.z > 0.0f ? 1.0f : -1.0f;
    const Vec3 m = m_distribution.sample_normal(side * wo, u);
    const Vec3 m_facing = side * m;  // the microfacet normal on wo's side
    const float cos_o = glm::dot(wo, m_facing);
    if (!(cos_o > 0.0f)) return std::nullopt;
    const float eta = index(wo.z) / index(-wo.z);  // n_incident / n_transmitted
    const float cos2_t = transmitted_cos2(cos_o, eta);
    const float fresnel = fresnel_dielectric_given(std::min(cos_o, 1.0f), cos2_t, eta);
    LobeDraw draw;
    if (uc < fresnel) {
        draw = {detail::reflect_about(wo, m_facing), kLobeGlossy | kLobeReflection};
        if (!(draw.wi.z * wo.z > 0.0f)) return std::nullopt;
    } else {
        const std::optional<Vec3> t = refract_given(-wo, m_facing, eta, cos_o, cos2_t);
        if (!t) return std::nullopt;
        draw = {glm::normalize(*t), kLobeGlossy | kLobeTransmission};
        if (!(draw.wi.z * wo.z < 0.0f)) return std::nullopt;
    }
    return draw;
}

}  // namespace rtlab
