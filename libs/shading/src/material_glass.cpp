// Material "glass": a smooth dielectric; the Fresnel term splits light between reflection and refraction.
//
// Parameters
//   kr        reflection colour or texture                               default 1
//   kt        transmission colour or texture (tinted glass)              default 1
//   ior       index of refraction inside                                 default 1.5
//   fresnel   weight kr by F and kt by 1 - F                             default true
//   + the other Whitted terms (builtin_params.cpp: kWhittedDoc): ior_outside (a glass shell around air is
//   an inner surface with ior 1 and ior_outside 1.5, or a reversed one), absorption (Beer-Lambert).
// Under total internal reflection the transmitted share goes to reflection. No direct light of its own.
#include "builtin_params.hpp"

namespace rtlab::shading_detail {

namespace {
class GlassMaterial final : public Material {
public:
    explicit GlassMaterial(Whitted w) : Material(std::move(w)) { local_terms_are_constant(); }
    RGB direct(const SurfaceTerms&, const Vec3&, const Vec3&, Convention) const override { return {}; }
    bool reflects_direct_light() const override { return false; }

protected:
    void local_terms(const TextureLookup&, SurfaceTerms&) const override {}
};

TypeSpec glass_spec() {
    TypeSpec s("smooth dielectric: kr and kt weighted by Fresnel");
    with_material_params(s);
    s.at("kr").defaults("1");
    s.at("kt").defaults("1");
    s.at("ior").defaults("1.5");
    s.at("fresnel").defaults("true");
    return s;
}
}  // namespace

void register_glass(MaterialRegistry& registry) {
    registry.add(
        "glass",
        [](const Params& p) -> std::shared_ptr<Material> {
            WhittedDefaults d;
            d.kr = RGB(1.0f);
            d.kt = RGB(1.0f);
            d.ior = 1.5f;
            d.fresnel = true;
            return std::make_shared<GlassMaterial>(read_whitted(p, d));
        },
        glass_spec());
}

}  // namespace rtlab::shading_detail
