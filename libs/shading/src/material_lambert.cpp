// Material "lambert": ideal diffuse reflection.
//
// Parameters
//   albedo   diffuse reflectance, colour or texture                      default 0.5
//   + the Whitted terms of every material (builtin_params.cpp: kWhittedDoc)
//
// physical: albedo / pi cos(theta_i); classic: albedo cos(theta_i).
#include <rtlab/shading/brdf.hpp>

#include "builtin_params.hpp"

namespace rtlab::shading_detail {

namespace {
class LambertMaterial final : public Material {
public:
    LambertMaterial(Whitted w, std::shared_ptr<const Texture> albedo)
        : Material(std::move(w)), m_albedo(std::move(albedo)) {
        if (m_albedo.is_constant()) local_terms_are_constant();
    }

    RGB direct(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, Convention c) const override {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return {};
        return t.diffuse * (c == Convention::physical ? wi.z * kInvPi : wi.z);
    }

    // Sampled: albedo / pi, cosine sampling.
    bool has_lobes() const override { return true; }
    bool lobes_use_choice() const override { return false; }
    RGB lobe_eval(const SurfaceTerms& t, const Vec3&, const Vec3&, TransportMode) const override {
        return t.diffuse * kInvPi;
    }
    float lobe_pdf(const SurfaceTerms&, const Vec3& wo, const Vec3& wi, TransportMode) const override {
        return LambertBrdf::pdf(wo, wi);
    }
    std::optional<LobeDraw> lobe_sample(const SurfaceTerms&, const Vec3& wo, float, const Vec2& u,
                                        TransportMode) const override {
        return LambertBrdf::sample(wo, u);
    }

protected:
    void local_terms(const TextureLookup& q, SurfaceTerms& t) const override { t.diffuse = m_albedo.eval(q); }

private:
    ColourChannel m_albedo;
};

TypeSpec lambert_spec() {
    TypeSpec s("ideal diffuse: albedo / pi (classic: albedo, no pi)");
    s.add("albedo", ParamKind::texture, "diffuse reflectance").defaults("0.5");
    return with_material_params(std::move(s));
}
}  // namespace

void register_lambert(MaterialRegistry& registry) {
    registry.add(
        "lambert",
        [](const Params& p) -> std::shared_ptr<Material> {
            auto albedo = colour_param(p, "albedo", RGB(0.5f));
            return std::make_shared<LambertMaterial>(read_whitted(p, {}), std::move(albedo));
        },
        lambert_spec());
}

}  // namespace rtlab::shading_detail
