// Test module, and the example of docs/sampled-materials.md: material "gloss", a glossy lobe about the mirror
// direction, f = color (e + 1) / (2 pi) cos^e(a), a the angle between wi and the mirror direction of wo. It is
// drawn from by sample_power_cosine, whose density is f / color, so each draw weighs color cos(theta_i); it is
// reciprocal (cos a is symmetric in wo and wi), and reflects at most color (the density integrates to at most 1,
// the cosine is at most 1).
#include <rtlab/core/param_checks.hpp>
#include <rtlab/scene/plugin_abi.hpp>
#include <rtlab/shading/bsdf.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <cmath>
#include <optional>

namespace {

using namespace rtlab;

class GlossMaterial final : public Material {
public:
    GlossMaterial(Whitted w, std::shared_ptr<const Texture> color, float exponent)
        : Material(std::move(w)), m_color(std::move(color)), m_exponent(exponent) {}

    // The whitted integrator's question: f cos(theta_i) for one light (physical), times pi when classic.
    RGB direct(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, Convention c) const override {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return {};
        const RGB f_cos = t.diffuse * (density(wo, wi) * wi.z);
        return c == Convention::physical ? f_cos : f_cos * kPi;
    }

protected:
    void local_terms(const TextureLookup& q, SurfaceTerms& t) const override { t.diffuse = m_color->eval(q); }

    // The sampled lobe, for the direct and path integrators. Material calls these with wo and wi above the
    // surface (it mirrors both when the viewer is below) and mixes kr, kt and opacity in around them.
    bool has_lobes() const override { return true; }
    RGB lobe_eval(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, TransportMode) const override {
        return t.diffuse * density(wo, wi);
    }
    float lobe_pdf(const SurfaceTerms&, const Vec3& wo, const Vec3& wi, TransportMode) const override {
        return density(wo, wi);
    }
    std::optional<LobeDraw> lobe_sample(const SurfaceTerms&, const Vec3& wo, float, const Vec2& u,
                                        TransportMode) const override {
        const Vec3 wi = sample_power_cosine(mirror(wo), m_exponent, u);
        if (!(wi.z > 0.0f)) return std::nullopt;  // below the surface: lost, as lobe_pdf integrates to less than 1
        return LobeDraw{wi, kLobeGlossy | kLobeReflection};
    }

private:
    static Vec3 mirror(const Vec3& w) { return {-w.x, -w.y, w.z}; }
    /// (e + 1) / (2 pi) cos^e(a): the density of sample_power_cosine about the mirror direction.
    float density(const Vec3& wo, const Vec3& wi) const {
        const float cos_a = glm::dot(mirror(wo), wi);
        return cos_a > 0.0f ? (m_exponent + 1.0f) / (2.0f * kPi) * std::pow(cos_a, m_exponent) : 0.0f;
    }

    std::shared_ptr<const Texture> m_color;
    float m_exponent;
};

std::shared_ptr<Material> make_gloss(const Params& p) {
    return std::make_shared<GlossMaterial>(read_whitted(p), texture_param(p, "color", RGB(0.8f)),
                                           float_in_range(p, "exponent", 50.0f, 0.0f, 10000.0f));
}

TypeSpec gloss_spec() {
    TypeSpec s("a glossy lobe about the mirror direction: color (e + 1) / (2 pi) cos^e");
    s.add("color", ParamKind::texture, "what the lobe reflects at most (keep it at most 1)").defaults("0.8");
    s.add("exponent", ParamKind::number, "e: larger is a sharper lobe").defaults("50").range(0, 10000);
    s.extend(material_shared_params(), "material");
    return s;
}

void register_types(PluginRegistries& r) { r.materials.add("gloss", make_gloss, gloss_spec()); }

}  // namespace

RTLAB_DEFINE_PLUGIN("gloss: a sampled glossy material", register_types)
