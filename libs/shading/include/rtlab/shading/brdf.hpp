#pragma once
/// \brief Reflectance models evaluated in the local shading frame (normal = +z).
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/shading/bsdf.hpp>
#include <rtlab/shading/optics.hpp>

#include <optional>

namespace rtlab {

/// \brief A BRDF f(wo, wi); both directions point away from the surface, in the local frame (n = +z).
/// Directions below the surface give black.
///
/// The models below also sample: pdf(wo, wi) is the solid-angle density of the directions sample(wo, uc, u)
/// draws for wo above the surface (uc picks the part, u the direction). It integrates to 1 minus the
/// share of draws that land below the surface, which sample() returns as nullopt (absorbed). A model mixes
/// its diffuse and specular parts in proportion to their colours' channel means.
class Brdf {
public:
    virtual ~Brdf() = default;
    virtual RGB eval(const Vec3& wo, const Vec3& wi) const = 0;
};

/// \brief Ideal diffuse: albedo / pi.
class LambertBrdf final : public Brdf {
public:
    explicit LambertBrdf(const RGB& albedo) : m_albedo(albedo) {}
    RGB eval(const Vec3& wo, const Vec3& wi) const override;
    /// Cosine sampling: cos(theta_i) / pi.
    static float pdf(const Vec3& wo, const Vec3& wi);
    static std::optional<LobeDraw> sample(const Vec3& wo, const Vec2& u);

private:
    RGB m_albedo;
};

/// \brief Energy-normalised Phong (Lafortune and Willems 1994): kd / pi + ks (e + 2) / (2 pi) cos^e(alpha),
/// alpha the angle between wi and the mirror direction of wo. Reciprocal, and conserves energy when
/// kd + ks <= 1 (the classic unnormalised Phong does neither).
class PhongBrdf final : public Brdf {
public:
    PhongBrdf(const RGB& kd, const RGB& ks, float exponent);
    RGB eval(const Vec3& wo, const Vec3& wi) const override;
    /// Cosine sampling for kd, (e + 1) / (2 pi) cos^e(alpha) about the mirror direction for ks.
    float pdf(const Vec3& wo, const Vec3& wi) const;
    std::optional<LobeDraw> sample(const Vec3& wo, float uc, const Vec2& u) const;

private:
    RGB m_kd, m_ks;
    float m_exponent;
};

/// \brief Energy-normalised Blinn-Phong: kd / pi + ks c(e) cos^e(theta_h), theta_h the angle between the
/// normal and the half vector, c(e) = (e + 2)(e + 4) / (8 pi (e + 2^(-e/2))): the lobe then reflects exactly
/// ks at normal incidence, its largest albedo, and conserves energy when kd + ks <= 1. (The common
/// (e + 8) / (8 pi) of Real-Time Rendering approximates c(e) and reflects up to 7.5% more than it
/// receives, at e ~ 9.)
class BlinnPhongBrdf final : public Brdf {
public:
    BlinnPhongBrdf(const RGB& kd, const RGB& ks, float exponent);
    RGB eval(const Vec3& wo, const Vec3& wi) const override;
    /// Cosine sampling for kd; for ks half vectors with density (e + 1) / (2 pi) cos^e(theta_h), mirrored:
    /// the lobe's density over wi is that over 4 (wo.h).
    float pdf(const Vec3& wo, const Vec3& wi) const;
    std::optional<LobeDraw> sample(const Vec3& wo, float uc, const Vec2& u) const;

private:
    RGB m_kd, m_ks;
    float m_exponent;
    float m_norm;  // c(e)
};

/// The microfacet normal distributions of CookTorranceBrdf.
enum class MicrofacetModel { ggx, beckmann };

/// \brief An isotropic microfacet normal distribution D(m) with its exact Smith masking function G1(v)
/// (Walter et al. 2007). GGX: D = alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2), G1 = 2 / (1 + sqrt(1 + alpha^2
/// tan^2)). Beckmann: D = exp(-tan^2 / alpha^2) / (pi alpha^2 cos^4), G1 from the erf form of Smith's
/// Lambda, not the rational approximation. alpha is the RMS slope width (Beckmann) or its GGX analogue.
class MicrofacetDistribution {
public:
    /// The smallest alpha: a narrower lobe is a mirror and belongs to the recursion's reflected ray. Below it
    /// the half vector of a grazing pair, wo + wi normalised in float, is rounding noise at the lobe's
    /// scale (cos_o = 1e-4 with alpha = 1e-4 gave albedos of 1.4 to 1.5 by half-vector quadrature; with
    /// alpha = 1e-3 they stay below 1).
    static constexpr float kMinAlpha = 1e-3f;

    /// alpha in [kMinAlpha, 1]; throws Error otherwise.
    MicrofacetDistribution(MicrofacetModel model, float alpha);
    /// From a user's perceptual roughness r in [0, 1]: alpha = r^2 (Burley 2012), so that r = 0.5 looks
    /// halfway between mirror and matte; r below sqrt(kMinAlpha) = 0.032 gives kMinAlpha. Error outside [0, 1].
    static MicrofacetDistribution from_roughness(MicrofacetModel model, float roughness);

    MicrofacetModel model() const { return m_model; }
    float alpha() const { return m_alpha; }

    /// D(m) for a unit microfacet normal m in the local frame; 0 below the surface. Normalised so that the
    /// projected microfacet area integrates to 1: the integral of D(m) cos(theta_m) over the hemisphere.
    float d(const Vec3& m) const;
    /// Smith G1(v): the fraction of microfacets facing the unit direction v that it sees unmasked;
    /// in [0, 1], 1 along the normal, 0 for v at or below the horizon.
    float g1(const Vec3& v) const;
    /// G1(v) / cos(theta_v), finite down to grazing v, where G1 and the cosine both go to 0.
    float g1_over_cos(const Vec3& v) const;

    /// A microfacet normal (upper hemisphere) for a viewer at wo (wo.z > 0). GGX: the normals wo sees,
    /// density G1(wo) max(0, wo.m) D(m) / cos(theta_o) (Heitz 2018, "Sampling the GGX distribution of
    /// visible normals", JCGT 7(4)): never a normal facing away, so fewer draws are lost than with D.
    /// Beckmann: D(m) cos(theta_m), the plain distribution (its visible normals have no closed-form sampler).
    Vec3 sample_normal(const Vec3& wo, const Vec2& u) const;
    /// The density of sample_normal over microfacet normals m.
    float normal_pdf(const Vec3& wo, const Vec3& m) const;

private:
    MicrofacetModel m_model;
    float m_alpha;
};

/// \brief Cook-Torrance: kd / pi + ks D(h) G1(wo) G1(wi) F(wo.h) / (4 cos_o cos_i), h the half vector, in
/// the form of Walter et al. 2007 (Cook and Torrance 1982 with a normalised D and the Smith G). The Lambert
/// part is not weighted by 1 - F, as in the 1982 model: energy is conserved when kd plus the lobe's
/// albedo stays below 1 (the lobe alone reflects at most 1 with Fresnel::one(), less at high roughness
/// where single scattering loses what bounces between microfacets).
class CookTorranceBrdf final : public Brdf {
public:
    /// ks scales the lobe (RGB(1) for a metal, whose colour is in the conductor's Fresnel); kd, ks >= 0.
    CookTorranceBrdf(const RGB& kd, const RGB& ks, const MicrofacetDistribution& distribution, const Fresnel& fresnel);
    RGB eval(const Vec3& wo, const Vec3& wi) const override;
    /// Cosine sampling for kd; for the lobe a normal from the distribution's sample_normal, mirrored (density
    /// normal_pdf / (4 wo.m)). The lobe is chosen in proportion to the channel mean of ks F(cos_o).
    float pdf(const Vec3& wo, const Vec3& wi) const;
    std::optional<LobeDraw> sample(const Vec3& wo, float uc, const Vec2& u) const;

private:
    RGB m_kd, m_ks;
    MicrofacetDistribution m_distribution;
    Fresnel m_fresnel;
};

/// \brief Ashikhmin and Shirley's anisotropic Phong (J. Graphics Tools 5(2), 2000): exponent nu along the
/// tangent (+x), nv along the bitangent (+y). Specular sqrt((nu + 1)(nv + 1)) / (8 pi) (n.h)^((nu h_x^2 +
/// nv h_y^2) / (1 - (n.h)^2)) / ((h.k) max(cos_o, cos_i)) F(h.k), F Schlick's with F0 = rs; diffuse
/// 28 rd / (23 pi) (1 - rs) (1 - (1 - cos_o / 2)^5) (1 - (1 - cos_i / 2)^5).
class AshikhminShirleyBrdf final : public Brdf {
public:
    /// rd, rs >= 0, and energy is conserved for rd, rs <= 1; nu, nv finite and >= 0.
    AshikhminShirleyBrdf(const RGB& rd, const RGB& rs, float nu, float nv);
    RGB eval(const Vec3& wo, const Vec3& wi) const override;
    /// The paper's own half-vector sampling (its section 3): phi_h = atan(sqrt((nu + 1) / (nv + 1))
    /// tan(pi u / 2)) per quadrant, cos(theta_h) = (1 - u')^(1 / (nu cos^2 phi_h + nv sin^2 phi_h + 1)), density
    /// sqrt((nu + 1)(nv + 1)) / (2 pi) (n.h)^(nu cos^2 + nv sin^2) over h, over 4 (wo.h) over wi; cosine sampling
    /// for the diffuse part. The lobe is chosen in proportion to the channel mean of Schlick's F at cos_o.
    float pdf(const Vec3& wo, const Vec3& wi) const;
    std::optional<LobeDraw> sample(const Vec3& wo, float uc, const Vec2& u) const;

private:
    RGB m_rd, m_rs;
    float m_nu, m_nv;
    float m_specular_norm;  // sqrt((nu + 1)(nv + 1)) / (8 pi)
};

}  // namespace rtlab
