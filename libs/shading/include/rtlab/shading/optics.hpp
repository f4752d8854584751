#pragma once
/// \brief Reflection, refraction and Fresnel terms: the geometric optics of the Whitted recursion.
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>

#include <cmath>
#include <optional>

namespace rtlab {

/// Mirror direction of the incident direction `d` (pointing towards the surface) about unit normal n.
inline Vec3 reflect(const Vec3& d, const Normal3& n) { return d - 2.0f * glm::dot(d, n) * n; }

/// Squared cosine of the transmitted angle, cos_t^2 = 1 - eta^2 (1 - cos_i^2), for the incident angle's
/// cosine cos_i and eta = n_incident / n_transmitted; <= 0 means total internal reflection. refract and
/// fresnel_dielectric both decide total internal reflection from this one value, so they agree at every angle.
float transmitted_cos2(float cos_i, float eta);

/// Refracted direction of unit incident direction `d` (pointing towards the surface) through a surface
/// with unit normal n facing the incident side, with eta = n_incident / n_transmitted.
/// nullopt on total internal reflection (transmitted_cos2 <= 0), exactly where fresnel_dielectric is 1.
std::optional<Vec3> refract(const Vec3& d, const Normal3& n, float eta);

/// Unpolarised Fresnel reflectance of a dielectric interface; cos_i = cos of the incident angle (> 0 on the
/// side the light comes from), eta = n_incident / n_transmitted. 1 under total internal reflection.
float fresnel_dielectric(float cos_i, float eta);

/// refract() and fresnel_dielectric() given the cosine and transmitted_cos2 they work out, for a caller that
/// asks both about one incidence (the Whitted recursion at a glass surface) and so works cos2_t out once.
/// refract_given takes cos_i = -dot(d, n); fresnel_dielectric_given takes cos_i clamped to [0, 1] and
/// cos2_t = transmitted_cos2 of that clamped cosine (the same number whenever the unclamped one is >= 0).
inline std::optional<Vec3> refract_given(const Vec3& d, const Normal3& n, float eta, float cos_i, float cos2_t) {
    if (cos2_t <= 0.0f) return std::nullopt;
    const float cos_t = std::sqrt(cos2_t);
    return eta * d + (eta * cos_i - cos_t) * n;
}

inline float fresnel_dielectric_given(float cos_i, float cos2_t, float eta) {
    if (cos2_t <= 0.0f) return 1.0f;
    const float cos_t = std::sqrt(cos2_t);
    // With eta = n_i / n_t: r_s = (eta cos_i - cos_t) / (eta cos_i + cos_t),
    // r_p = (cos_i - eta cos_t) / (cos_i + eta cos_t).
    const float r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (r_s * r_s + r_p * r_p);
}

/// Schlick's approximation of fresnel_dielectric, the fast variant charted against it.
float fresnel_schlick(float cos_i, float eta);

/// Exact unpolarised Fresnel reflectance of a conductor: light in a medium of index n_i meets a metal of
/// complex index n_t (eta_t + i k_t); eta = eta_t / n_i and k = k_t / n_i (for a metal in air, the
/// tabulated n and k). Unlike fresnel_dielectric, eta is the far side over the near side, the way measured
/// metal data is given; with k = 0 it equals fresnel_dielectric(cos_i, 1 / eta), total internal reflection
/// included. Needs eta > 0 and k >= 0.
float fresnel_conductor(float cos_i, float eta, float k);

/// \brief A complex index of refraction eta + i k per RGB channel (relative to the outside medium).
struct ComplexIor {
    RGB eta;
    RGB k;
};

/// fresnel_conductor per channel.
RGB fresnel_conductor(float cos_i, const ComplexIor& ior);

/// Measured metals at the three wavelengths tabulated nearest to 650 / 550 / 450 nm (R, G, B), for a metal
/// in air. Gold, silver and copper: P. B. Johnson and R. W. Christy, "Optical constants of the noble metals",
/// Phys. Rev. B 6, 4370 (1972), at 659.5, 548.6 and 450.9 nm. Aluminium: A. D. Rakic, "Algorithm for the
/// determination of intrinsic optical constants of metal films: application to aluminum", Appl. Opt. 34,
/// 4755 (1995), at 652.3, 563.6 and 442.8 nm. (Both as tabulated in the refractiveindex.info database.)
/// Single wavelengths, not averages over the sRGB primaries' spectra: good for colour, not for spectra.
inline constexpr ComplexIor kGold{{0.14f, 0.43f, 1.38f}, {3.697f, 2.455f, 1.914f}};
inline constexpr ComplexIor kSilver{{0.05f, 0.06f, 0.04f}, {4.483f, 3.586f, 2.657f}};
inline constexpr ComplexIor kCopper{{0.22f, 1.02f, 1.24f}, {3.747f, 2.577f, 2.397f}};
inline constexpr ComplexIor kAluminium{{1.5724f, 1.0728f, 0.6079f}, {7.7354f, 6.7839f, 5.3676f}};

/// \brief The Fresnel factor of a specular lobe: an exact dielectric, an exact conductor, or 1.
class Fresnel {
public:
    /// A dielectric surface of relative index eta = n_surface / n_outside (1.5 for glass in air); light
    /// reaching it from inside (eta < 1) is totally reflected beyond the critical angle. Needs eta > 0.
    static Fresnel dielectric(float eta);
    /// A conductor of complex relative index eta + i k per channel (e.g. kGold). Needs eta > 0, k >= 0.
    static Fresnel conductor(const ComplexIor& ior);
    /// Reflects everything at every angle: an idealised mirror, and the white-furnace test.
    static Fresnel one();

    /// Reflectance for the cosine of the angle between the light and the (micro)surface normal.
    RGB eval(float cos_i) const;

private:
    enum class Kind { dielectric, conductor, one };
    Fresnel(Kind kind, const ComplexIor& ior) : m_kind(kind), m_ior(ior) {}

    Kind m_kind;
    ComplexIor m_ior;  // for a dielectric, eta.r holds 1 / eta, the form fresnel_dielectric takes
};

}  // namespace rtlab
