// Material "mirror": a perfect mirror; no direct light of its own, everything comes through kr.
//
// Parameters
//   kr       mirror reflectance, colour or texture                       default 1
//   + the other Whitted terms (builtin_params.cpp: kWhittedDoc); with fresnel = true and an ior the
//   reflectance is kr F(theta), a dielectric's reflection without its transmission.
#include "builtin_params.hpp"

namespace rtlab::shading_detail {

namespace {
class MirrorMaterial final : public Material {
public:
    explicit MirrorMaterial(Whitted w) : Material(std::move(w)) { local_terms_are_constant(); }
    RGB direct(const SurfaceTerms&, const Vec3&, const Vec3&, Convention) const override { return {}; }
    bool reflects_direct_light() const override { return false; }

protected:
    void local_terms(const TextureLookup&, SurfaceTerms&) const override {}
};

TypeSpec mirror_spec() {
    TypeSpec s("perfect mirror: all light through kr");
    with_material_params(s);
    s.at("kr").defaults("1");
    return s;
}
}  // namespace

void register_mirror(MaterialRegistry& registry) {
    registry.add(
        "mirror",
        [](const Params& p) -> std::shared_ptr<Material> {
            WhittedDefaults d;
            d.kr = RGB(1.0f);
            return std::make_shared<MirrorMaterial>(read_whitted(p, d));
        },
        mirror_spec());
}

}  // namespace rtlab::shading_detail
