// Test module: registers names that are taken, to test that the host refuses it naming both owners.
// Without SELF_CLASH: material "toon" (the toon example's), texture "checker" (a built-in) and the free
// material "duplicate-only", which must not be registered either when the module is refused. With
// SELF_CLASH: material "twice" twice, which its own registration reports.
#include <rtlab/scene/plugin_abi.hpp>

namespace {
class Black final : public rtlab::Material {
public:
    Black() : Material(Whitted{}) {}
    rtlab::RGB direct(const rtlab::SurfaceTerms&, const rtlab::Vec3&, const rtlab::Vec3&,
                      rtlab::Convention) const override {
        return {};
    }

protected:
    void local_terms(const rtlab::TextureLookup&, rtlab::SurfaceTerms&) const override {}
};

std::shared_ptr<rtlab::Material> make_black(const rtlab::Params&) { return std::make_shared<Black>(); }
std::shared_ptr<rtlab::Texture> make_nothing(const rtlab::Params&) { return nullptr; }
// Parameterless types: a declaration with a doc only.
rtlab::TypeSpec no_params() { return rtlab::TypeSpec("takes no parameters"); }

void register_types(rtlab::PluginRegistries& r) {
#if defined(SELF_CLASH)
    r.materials.add("twice", make_black, no_params());
    r.materials.add("twice", make_black, no_params());
#else
    r.materials.add("duplicate-only", make_black, no_params());
    r.materials.add("toon", make_black, no_params());
    r.textures.add("checker", make_nothing, no_params());
#endif
}

}  // namespace

RTLAB_DEFINE_PLUGIN("a module registering taken names", register_types)
