#include <rtlab/core/error.hpp>
#include <rtlab/shading/brdf.hpp>

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

PhongBrdf::PhongBrdf(const RGB& kd, const RGB& ks, float exponent) : m_kd(kd), m_ks(ks), m_exponent(exponent) {
    check_exponent(exponent, "phong");
}

RGB PhongBrdf::eval(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere_above(wo, wi)) return {};
    const Vec3 mirror(-wo.x, -wo.y, wo.z);  // reflection of wo about +z
    const float cos_alpha = std::max(0.0f, glm::dot(mirror, wi));
    const float lobe = (m_exponent + 2.0f) * (0.5f * kInvPi) * std::pow(cos_alpha, m_exponent);
    return m_kd * kInvPi + m_ks * lobe;
}

BlinnPhongBrdf::BlinnPhongBrdf(const RGB& kd, const RGB& ks, float exponent)
    : m_kd(kd), m_ks(ks), m_exponent(exponent) {
    check_exponent(exponent, "blinn-phong");
}

RGB BlinnPhongBrdf::eval(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere_above(wo, wi)) return {};
    const Vec3 h = glm::normalize(wo + wi);
    const float lobe = (m_exponent + 8.0f) * (0.125f * kInvPi) * std::pow(std::max(0.0f, h.z), m_exponent);
    return m_kd * kInvPi + m_ks * lobe;
}

}  // namespace rtlab
