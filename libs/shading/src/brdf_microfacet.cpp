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

float MicrofacetDistribution::g1(const Vec3& v) const {
    // The product can round a hair above 1 near the normal.
    return std::min(1.0f, v.z * g1_over_cos(v));
}

}  // namespace rtlab
