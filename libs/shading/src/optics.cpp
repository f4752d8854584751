#include <rtlab/core/error.hpp>
#include <rtlab/shading/optics.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace rtlab {

float transmitted_cos2(float cos_i, float eta) {
    // (1 - eta)(1 + eta) + eta^2 cos_i^2 rather than 1 - eta^2 sin_i^2: no cancellation for eta near 1 at
    // grazing incidence. Out of line so that every caller rounds it the same way.
    const float cos2_i = std::min(cos_i * cos_i, 1.0f);
    return (1.0f - eta) * (1.0f + eta) + eta * eta * cos2_i;
}

std::optional<Vec3> refract(const Vec3& d, const Normal3& n, float eta) {
    const float cos_i = -glm::dot(d, n);
    return refract_given(d, n, eta, cos_i, transmitted_cos2(cos_i, eta));
}

float fresnel_dielectric(float cos_i, float eta) {
    cos_i = std::clamp(cos_i, 0.0f, 1.0f);
    return fresnel_dielectric_given(cos_i, transmitted_cos2(cos_i, eta), eta);
}

float fresnel_schlick(float cos_i, float eta) {
    cos_i = std::clamp(cos_i, 0.0f, 1.0f);
    // Going into the optically thinner medium, Schlick's formula needs the transmitted angle's cosine.
    if (eta > 1.0f) {
        const float cos2_t = transmitted_cos2(cos_i, eta);
        if (cos2_t <= 0.0f) return 1.0f;
        cos_i = std::sqrt(cos2_t);
    }
    const float r0 = (1.0f - eta) / (1.0f + eta);
    const float f0 = r0 * r0;
    const float m = 1.0f - cos_i;
    return f0 + (1.0f - f0) * (m * m) * (m * m) * m;
}

float fresnel_conductor(float cos_i, float eta, float k) {
    cos_i = std::clamp(cos_i, 0.0f, 1.0f);
    const float cos2 = cos_i * cos_i;
    const float sin2 = 1.0f - cos2;
    // n cos_t = sqrt((eta + i k)^2 - sin^2) = a + i b; the textbook real form of |r_s|^2 and |r_p|^2
    // (Born and Wolf), which needs only a and a^2 + b^2.
    // eta^2 - k^2 - sin^2, with eta^2 - 1 factored so that eta near 1 keeps its digits at grazing incidence.
    const float t0 = (eta - 1.0f) * (eta + 1.0f) - k * k + cos2;
    const float a2b2 = std::sqrt(t0 * t0 + 4.0f * eta * eta * k * k);
    const float a = std::sqrt(std::max(0.0f, 0.5f * (a2b2 + t0)));
    const float s_num = a2b2 + cos2 - 2.0f * a * cos_i;
    const float s_den = a2b2 + cos2 + 2.0f * a * cos_i;
    // Zero only at grazing incidence on a medium matching the outside (eta = 1, k = 0); like
    // fresnel_dielectric, call that grazing limit total reflection.
    if (s_den == 0.0f) return 1.0f;
    const float r_s = s_num / s_den;
    const float p0 = a2b2 * cos2 + sin2 * sin2;
    const float p1 = 2.0f * a * cos_i * sin2;
    const float r_p = r_s * (p0 - p1) / (p0 + p1);
    return 0.5f * (r_s + r_p);
}

RGB fresnel_conductor(float cos_i, const ComplexIor& ior) {
    return {fresnel_conductor(cos_i, ior.eta.r, ior.k.r), fresnel_conductor(cos_i, ior.eta.g, ior.k.g),
            fresnel_conductor(cos_i, ior.eta.b, ior.k.b)};
}

namespace {
void check_ior(const ComplexIor& ior, const char* what) {
    for (int c = 0; c < 3; ++c) {
        if (!(ior.eta[c] > 0.0f) || !std::isfinite(ior.eta[c]) || !(ior.k[c] >= 0.0f) || !std::isfinite(ior.k[c]))
            throw Error(std::string("fresnel ") + what +
                        ": index of refraction must have eta > 0 and k >= 0 (finite), got eta " +
                        std::to_string(ior.eta[c]) + ", k " + std::to_string(ior.k[c]) + " in channel " +
                        std::to_string(c));
    }
}
}  // namespace

Fresnel Fresnel::dielectric(float eta) {
    check_ior({RGB(eta), RGB(0.0f)}, "dielectric");
    return {Kind::dielectric, {RGB(1.0f / eta), RGB(0.0f)}};
}

Fresnel Fresnel::conductor(const ComplexIor& ior) {
    check_ior(ior, "conductor");
    return {Kind::conductor, ior};
}

Fresnel Fresnel::one() { return {Kind::one, {RGB(1.0f), RGB(0.0f)}}; }

RGB Fresnel::eval(float cos_i) const {
    switch (m_kind) {
        case Kind::dielectric:
            return RGB(fresnel_dielectric(cos_i, m_ior.eta.r));
        case Kind::conductor:
            return fresnel_conductor(cos_i, m_ior);
        case Kind::one:
            break;
    }
    return RGB(1.0f);
}

}  // namespace rtlab
