// Material "cook-torrance": a Lambert base plus a microfacet specular lobe (GGX or Beckmann, Smith masking),
// with a dielectric or conductor Fresnel term.
//
// Parameters
//   kd             diffuse colour or texture                              default 0
//   ks             lobe scale, colour or texture                          default 1
//   roughness      perceptual roughness in [0, 1] (alpha = r^2), number
//                  or texture (scalar: channel mean)                      default 0.3
//   distribution   ggx or beckmann                                        default ggx
//   metal          gold, silver, copper or aluminium: a measured
//                  conductor (instead of eta and k)
//   eta, k         a conductor's complex index per channel (colours), as
//                  tabulated for a metal in vacuum; both or neither
//   + the Whitted terms of every material (builtin_params.cpp: kWhittedDoc); without metal or eta/k the
//   lobe is a dielectric's, of relative index ior / ior_outside (ior default 1.5 here).
//
// Index conventions: Fresnel::dielectric and the conductor's eta + i k both take the surface's index over
// the outside's (1.5 for glass in air), so the dielectric gets ior / ior_outside and a metal's tabulated
// n and k are divided by ior_outside (a gold sphere in water). The recursion's own fresnel_dielectric for
// kr and kt takes n_incident / n_transmitted instead (whitted.cpp). The lobe uses the same relative index
// on both sides of the surface: cook-torrance is an opaque coating, not an interface to refract through.
//
// physical: CookTorranceBrdf times cos(theta_i); classic: the same times pi, so the diffuse part is kd (n.l).
#include <rtlab/shading/brdf.hpp>
#include <rtlab/shading/optics.hpp>

#include "builtin_params.hpp"
#include "sampled_reflection.hpp"

#include <algorithm>
#include <string>

namespace rtlab::shading_detail {

namespace {
class CookTorranceMaterial final : public SampledReflection<CookTorranceMaterial> {
public:
    CookTorranceMaterial(Whitted w, std::shared_ptr<const Texture> kd, std::shared_ptr<const Texture> ks,
                         std::shared_ptr<const Texture> roughness, MicrofacetModel model, const Fresnel& fresnel)
        : SampledReflection(std::move(w)),
          m_kd(std::move(kd)),
          m_ks(std::move(ks)),
          m_roughness(std::move(roughness), 0.0f, 1.0f, 1.0f),  // a NaN roughness is matte, never a spike
          m_model(model),
          m_fresnel(fresnel) {
        if (m_kd.is_constant() && m_ks.is_constant() && m_roughness.is_constant()) local_terms_are_constant();
    }

    RGB direct(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, Convention c) const override {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return {};
        const CookTorranceBrdf f(t.diffuse, t.specular, MicrofacetDistribution::from_roughness(m_model, t.shape_u),
                                 m_fresnel);
        return f.eval(wo, wi) * (c == Convention::physical ? wi.z : wi.z * kPi);
    }

    /// The physical model of brdf.hpp at one hit: SampledReflection's lobes.
    CookTorranceBrdf brdf(const SurfaceTerms& t) const {
        return {t.diffuse, t.specular, MicrofacetDistribution::from_roughness(m_model, t.shape_u), m_fresnel};
    }

protected:
    void local_terms(const TextureLookup& q, SurfaceTerms& t) const override {
        t.diffuse = m_kd.eval(q);
        t.specular = m_ks.eval(q);
        t.shape_u = m_roughness.eval(q);
    }

private:
    ColourChannel m_kd, m_ks;
    ScalarChannel m_roughness;
    MicrofacetModel m_model;
    Fresnel m_fresnel;
};

ComplexIor relative_to(const ComplexIor& ior, float outside) { return {ior.eta / outside, ior.k / outside}; }

Fresnel read_fresnel(const Params& p, const Material::Whitted& w) {
    const bool has_metal = p.has("metal"), has_eta = p.has("eta"), has_k = p.has("k");
    if (has_metal && (has_eta || has_k)) fail_param(p, "metal", "and eta/k are both given; give one");
    if (has_eta != has_k) fail_param(p, has_eta ? "k" : "eta", "is missing: a conductor needs both eta and k");
    if (has_metal) {
        const std::string m = one_of(p, "metal", "gold", {"gold", "silver", "copper", "aluminium"});
        const ComplexIor& ior = m == "gold" ? kGold : m == "silver" ? kSilver : m == "copper" ? kCopper : kAluminium;
        return Fresnel::conductor(relative_to(ior, w.ior_outside));
    }
    if (has_eta) {
        const ComplexIor ior{finite_rgb(p, "eta", RGB(1.0f)), finite_rgb(p, "k", RGB(0.0f))};
        if (!(std::min({ior.eta.r, ior.eta.g, ior.eta.b}) > 0.0f)) fail_param(p, "eta", "must be > 0");
        if (!(std::min({ior.k.r, ior.k.g, ior.k.b}) >= 0.0f)) fail_param(p, "k", "must be >= 0");
        return Fresnel::conductor(relative_to(ior, w.ior_outside));
    }
    return Fresnel::dielectric(w.ior_inside / w.ior_outside);  // n_surface / n_outside: 1.5 for glass in air
}

TypeSpec cook_torrance_spec() {
    TypeSpec s(
        "microfacet: kd / pi + ks D G F / (4 cos_o cos_i); a conductor (metal, or eta and k) or else a "
        "dielectric lobe of index ior / ior_outside. Classic convention: times pi");
    s.add("kd", ParamKind::texture, "diffuse colour").defaults("0");
    s.add("ks", ParamKind::texture, "scale of the specular lobe").defaults("1");
    s.add("roughness", ParamKind::scalar, "perceptual roughness, alpha = roughness^2").defaults("0.3").range(0, 1);
    s.add("distribution", ParamKind::word, "the microfacet distribution D").defaults("ggx").allow({"ggx", "beckmann"});
    s.add("metal", ParamKind::word, "a measured conductor, instead of eta and k")
        .allow({"gold", "silver", "copper", "aluminium"});
    s.add("eta", ParamKind::colour, "a conductor's index per channel, relative to vacuum (> 0; with k)");
    s.add("k", ParamKind::colour, "a conductor's extinction per channel, relative to vacuum (with eta)");
    with_material_params(s);
    s.at("ior").defaults("1.5");
    return s;
}
}  // namespace

void register_cook_torrance(MaterialRegistry& registry) {
    registry.add(
        "cook-torrance",
        [](const Params& p) -> std::shared_ptr<Material> {
            auto kd = colour_param(p, "kd", RGB(0.0f));
            auto ks = colour_param(p, "ks", RGB(1.0f));
            auto roughness = scalar_param(p, "roughness", 0.3f, 0.0f, 1.0f);
            const MicrofacetModel model = one_of(p, "distribution", "ggx", {"ggx", "beckmann"}) == "ggx"
                                              ? MicrofacetModel::ggx
                                              : MicrofacetModel::beckmann;
            WhittedDefaults d;
            d.ior = 1.5f;
            Material::Whitted w = read_whitted(p, d);
            const Fresnel fresnel = read_fresnel(p, w);
            return std::make_shared<CookTorranceMaterial>(std::move(w), std::move(kd), std::move(ks),
                                                          std::move(roughness), model, fresnel);
        },
        cook_torrance_spec());
}

}  // namespace rtlab::shading_detail
