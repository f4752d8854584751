#include <rtlab/shading/optics.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

std::optional<Vec3> refract(const Vec3& d, const Normal3& n, float eta) {
    const float cos_i = -glm::dot(d, n);
    const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) return std::nullopt;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    return eta * d + (eta * cos_i - cos_t) * n;
}

float fresnel_dielectric(float cos_i, float eta) {
    cos_i = std::clamp(cos_i, 0.0f, 1.0f);
    const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) return 1.0f;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    // With eta = n_i / n_t: r_s = (eta cos_i - cos_t) / (eta cos_i + cos_t), r_p = (cos_i - eta cos_t) / (cos_i + eta cos_t).
    const float r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (r_s * r_s + r_p * r_p);
}

float fresnel_schlick(float cos_i, float eta) {
    cos_i = std::clamp(cos_i, 0.0f, 1.0f);
    // Going into the optically thinner medium, Schlick's formula needs the transmitted angle's cosine.
    if (eta > 1.0f) {
        const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
        if (sin2_t >= 1.0f) return 1.0f;
        cos_i = std::sqrt(1.0f - sin2_t);
    }
    const float r0 = (1.0f - eta) / (1.0f + eta);
    const float f0 = r0 * r0;
    const float m = 1.0f - cos_i;
    return f0 + (1.0f - f0) * (m * m) * (m * m) * m;
}

}  // namespace rtlab
