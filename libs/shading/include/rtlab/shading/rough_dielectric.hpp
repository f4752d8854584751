#pragma once
/// \brief A rough dielectric interface: microfacet reflection and refraction (Walter et al. 2007).
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/shading/brdf.hpp>
#include <rtlab/shading/bsdf.hpp>

#include <optional>

namespace rtlab {

/// \brief B. Walter, S. Marschner, H. Li and K. Torrance, "Microfacet models for refraction through rough
/// surfaces", EGSR 2007: an interface between the outside (above, +z) and a medium of relative index eta =
/// n_inside / n_outside (below), its microfacets distributed by a MicrofacetDistribution with separable Smith
/// masking, each a smooth dielectric with the exact Fresnel term.
///
/// Directions in the local frame as in bsdf.hpp; either may be above or below. With m the (generalised) half
/// vector, m = normalise(n_o wo + n_i wi) turned upwards, n_o and n_i the indices on wo's and wi's sides:
///   reflection    f = F D G1(wo) G1(wi) / (4 |cos_o| |cos_i|)
///   transmission  f = |wo.m| |wi.m| / (|cos_o| |cos_i|) (1 - F) D G1(wo) G1(wi) n^2 / (n_i (wi.m) + n_o (wo.m))^2
/// with n = n_o in radiance mode (Walter's eq. 21, light from wi to wo) and n = n_i in importance mode (its
/// adjoint), so that f_radiance(wo, wi) / n_o^2 = f_radiance(wi, wo) / n_i^2 and f_importance(wo, wi) =
/// f_radiance(wi, wo). Sampling: a normal from the distribution's sample_normal for the side wo is on, then
/// reflection with probability F and refraction otherwise. Single scattering: light that would bounce between
/// microfacets is lost, more at high roughness.
class RoughDielectricBsdf {
public:
    /// eta = n_inside / n_outside > 0 and finite; eta = 1 is an index-matched interface (no reflection).
    RoughDielectricBsdf(const MicrofacetDistribution& distribution, float eta);

    /// f(wo, wi) (not times the cosine).
    float eval(const Vec3& wo, const Vec3& wi, TransportMode mode) const;
    /// The solid-angle density of sample()'s directions.
    float pdf(const Vec3& wo, const Vec3& wi) const;
    /// A direction with flags glossy and reflection or transmission; nullopt when the microfacet sends it to
    /// the wrong side (absorbed).
    std::optional<LobeDraw> sample(const Vec3& wo, float uc, const Vec2& u) const;

private:
    /// What eval and pdf share about one pair of directions.
    struct Pair {
        Vec3 m;                        // the half vector, m.z > 0
        float n_o = 1.0f, n_i = 1.0f;  // indices on wo's and wi's sides
        float fresnel = 0.0f;          // reflectance at the microfacet, seen from wo's side
        bool reflect = false;
    };
    std::optional<Pair> pair(const Vec3& wo, const Vec3& wi) const;
    float index(float z) const { return z > 0.0f ? 1.0f : m_eta; }

    MicrofacetDistribution m_distribution;
    float m_eta;
};

}  // namespace rtlab
