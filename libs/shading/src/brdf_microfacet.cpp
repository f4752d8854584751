// The GGX and Beckmann microfacet distributions with their exact Smith masking functions, after
// B. Walter, S. Marschner, H. Li and K. Torrance, "Microfacet models for refraction through rough
// surfaces", EGSR 2007. Everything is written in terms of the cosine z and sine s of the angle to the
// normal, never tan = s / z or 1 - z^2, so that directions at the horizon and along the normal need no
// special cases and no cancellation spoils narrow lobes.
#include <rtlab/shading/brdf.hpp>

#include "brdf_local.hpp"

#include <cmath>
#include <string>

namespace rtlab {

MicrofacetDistribution::MicrofacetDistribution(MicrofacetModel model, float alpha) : m_model(model), m_alpha(alpha) {
    detail::check_parameter(alpha >= kMinAlpha && alpha <= 1.0f, "microfacet distribution",
                            "alpha must be in [1e-3, 1]", alpha);
}

MicrofacetDistribution MicrofacetDistribution::from_roughness(MicrofacetModel model, float roughness) {
    detail::check_parameter(roughness >= 0.0f && roughness <= 1.0f, "microfacet distribution",
                            "roughness must be in [0, 1]", roughness);
    return {model, std::max(kMinAlpha, roughness * roughness)};
}

float MicrofacetDistribution::d(const Vec3& m) const {
    if (!(m.z > 0.0f)) return 0.0f;
    const float z2 = m.z * m.z;
    const float s2 = m.x * m.x + m.y * m.y;
    const float a2 = m_alpha * m_alpha;
    if (m_model == MicrofacetModel::ggx) {
        // cos^4 (alpha^2 + tan^2)^2 = (alpha^2 z^2 + s^2)^2 for a unit m.
        const float q = a2 * z2 + s2;
        return a2 / (kPi * q * q);
    }
    const float e = std::exp(-s2 / (z2 * a2));
    // Once the exponential underflows, z^4 may have too; the value is 0 either way.
    return e == 0.0f ? 0.0f : e / (kPi * a2 * z2 * z2);
}

float MicrofacetDistribution::g1_over_cos(const Vec3& v) const {
    if (!(v.z > 0.0f)) return 0.0f;
    const float z = v.z;
    const float alpha_s = m_alpha * std::sqrt(v.x * v.x + v.y * v.y);
    if (m_model == MicrofacetModel::ggx) {
        // 2 / (1 + sqrt(1 + alpha^2 tan^2)), divided by z.
        return 2.0f / (z + std::sqrt(z * z + alpha_s * alpha_s));
    }
    // G1 = 1 / (1 + Lambda), Lambda(a) = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)), a = z / (alpha s):
    // G1 / z = 2 / (z (1 + erf(a)) + alpha s exp(-a^2) / sqrt(pi)); a = +inf along the normal gives 1 / z.
    constexpr float kInvSqrtPi = std::numbers::inv_sqrtpi_v<float>;
    const float a = z / alpha_s;
    return 2.0f / (z * (1.0f + std::erf(a)) + alpha_s * std::exp(-a * a) * kInvSqrtPi);
}

Vec3 MicrofacetDistribution::sample_normal(const Vec3& wo, const Vec2& u) const {
    if (m_model == MicrofacetModel::beckmann) {
        // tan^2(theta_m) = -alpha^2 log(1 - u): the slopes are Gaussian; m from the slope, not from angles,
        // so narrow lobes keep their sines.
        const float tan_m = m_alpha * std::sqrt(-std::log1p(-u.x));
        const float phi = 2.0f * kPi * u.y;
        return glm::normalize(Vec3(tan_m * std::cos(phi), tan_m * std::sin(phi), 1.0f));
    }
    // Heitz 2018: stretch wo to the hemisphere configuration of alpha = 1, sample the projected area of a
    // half disk (a disk, its far half squashed by how much the viewer sees of it), unstretch.
    const Vec3 v = glm::normalize(Vec3(m_alpha * wo.x, m_alpha * wo.y, wo.z));
    const float len2 = v.x * v.x + v.y * v.y;
    const Vec3 t1 = len2 > 0.0f ? Vec3(-v.y, v.x, 0.0f) / std::sqrt(len2) : Vec3(1.0f, 0.0f, 0.0f);
    const Vec3 t2 = glm::cross(v, t1);
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + v.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 n = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * v;
    return glm::normalize(Vec3(m_alpha * n.x, m_alpha * n.y, std::max(0.0f, n.z)));
}

float MicrofacetDistribution::normal_pdf(const Vec3& wo, const Vec3& m) const {
    if (m_model == MicrofacetModel::beckmann) return m.z > 0.0f ? d(m) * m.z : 0.0f;
    return g1_over_cos(wo) * std::max(0.0f, glm::dot(wo, m)) * d(m);
}

float MicrofacetDistribution::g1(const Vec3& v) const {
    // The product can round a hair above 1 near the normal.
    return std::min(1.0f, v.z * g1_over_cos(v));
}

}  // namespace rtlab
