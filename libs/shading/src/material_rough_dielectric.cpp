// Material "rough-dielectric": frosted glass, a rough interface that reflects and refracts through
// microfacets (Walter et al. 2007, RoughDielectricBsdf of rough_dielectric.hpp).
//
// Parameters
//   roughness      perceptual roughness in [0, 1] (alpha = r^2, at least 1e-3), number or texture
//                  (scalar: channel mean)                                 default 0.2
//   distribution   ggx or beckmann                                        default ggx
//   ior            index of refraction inside (must differ from ior_outside)   default 1.5
//   + the keys every material shares (material_shared_params()); kr and kt (default 0) are smooth delta
//   lobes mixed in as material.hpp describes.
//
// Sampled (eval/pdf/sample): the full BSDF, both sides. direct() (the Whitted integrator, which turns the
// frame towards the viewer and cannot tell the sides apart) gives the reflection lobe as seen from outside,
// times cos(theta_i), and times pi in the classic convention; the transmitted light needs a sampling
// integrator.
#include <rtlab/shading/rough_dielectric.hpp>

#include "builtin_params.hpp"

#include <string>

namespace rtlab::shading_detail {

namespace {
class RoughDielectricMaterial final : public Material {
public:
    RoughDielectricMaterial(Whitted w, std::shared_ptr<const Texture> roughness, MicrofacetModel model)
        : Material(std::move(w)),
          m_roughness(std::move(roughness), 0.0f, 1.0f, 1.0f),  // a NaN roughness is matte, never a spike
          m_model(model) {
        if (m_roughness.is_constant()) local_terms_are_constant();
    }

    RGB direct(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, Convention c) const override {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return {};
        const float f = bsdf(t).eval(wo, wi, TransportMode::radiance);
        return RGB(f * (c == Convention::physical ? wi.z : wi.z * kPi));
    }

    bool has_lobes() const override { return true; }
    bool lobes_transmit() const override { return true; }
    RGB lobe_eval(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, TransportMode mode) const override {
        return RGB(bsdf(t).eval(wo, wi, mode));
    }
    float lobe_pdf(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, TransportMode) const override {
        return bsdf(t).pdf(wo, wi);
    }
    std::optional<LobeDraw> lobe_sample(const SurfaceTerms& t, const Vec3& wo, float uc, const Vec2& u,
                                        TransportMode) const override {
        return bsdf(t).sample(wo, uc, u);
    }

protected:
    void local_terms(const TextureLookup& q, SurfaceTerms& t) const override { t.shape_u = m_roughness.eval(q); }

private:
    RoughDielectricBsdf bsdf(const SurfaceTerms& t) const {
        return {MicrofacetDistribution::from_roughness(m_model, t.shape_u), ior_inside() / ior_outside()};
    }

    ScalarChannel m_roughness;
    MicrofacetModel m_model;
};
TypeSpec rough_dielectric_spec() {
    TypeSpec s(
        "rough dielectric (frosted glass; Walter et al. 2007): microfacet reflection and refraction through an "
        "interface of index ior / ior_outside. Whitted: the reflection lobe only; the transmission needs a "
        "sampling integrator");
    s.add("roughness", ParamKind::scalar, "perceptual roughness, alpha = roughness^2 (at least 1e-3)")
        .defaults("0.2")
        .range(0, 1);
    s.add("distribution", ParamKind::word, "the microfacet distribution D").defaults("ggx").allow({"ggx", "beckmann"});
    with_material_params(s);
    s.at("ior").defaults("1.5");
    return s;
}
}  // namespace

void register_rough_dielectric(MaterialRegistry& registry) {
    registry.add(
        "rough-dielectric",
        [](const Params& p) -> std::shared_ptr<Material> {
            auto roughness = scalar_param(p, "roughness", 0.2f, 0.0f, 1.0f);
            const MicrofacetModel model = read_microfacet_model(p);
            Material::Whitted w = read_whitted(p, glass_defaults());
            if (w.ior_inside == w.ior_outside)
                fail_param(p, "ior", "equals ior_outside: an index-matched interface does not scatter");
            return std::make_shared<RoughDielectricMaterial>(std::move(w), std::move(roughness), model);
        },
        rough_dielectric_spec());
}

}  // namespace rtlab::shading_detail
