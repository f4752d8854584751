// Plugin module "toon": a toon (cel) shading material, registered as material "toon".
//
// Light is not graded smoothly but cut into `levels` flat bands: the lit fraction n.l in (0, 1] becomes
// ceil(n.l * levels) / levels, so a sphere under one light shows `levels` rings of flat colour and a
// dark side. A hard-edged highlight and a dark silhouette band complete the cartoon look.
//
// Parameters
//   color           base colour, colour or texture                                  default 0.8
//   levels          number of lit bands, 1..16                                       default 3
//   highlight       colour added where the mirror direction is within the highlight  default 0 (none)
//   highlight_size  cosine between the mirror direction and the viewer above which   default 0.97
//                   the highlight shows, in [0, 1)
//   outline         n.v below which the surface is drawn black (silhouette), [0, 1)  default 0 (none)
//   + the keys every material shares (kr, kt, ior, ior_outside, fresnel, emission, opacity, absorption):
//     declared with material_shared_params() and read with read_whitted(), as the built-in materials do
//
// Bands are flat under lights whose arriving intensity does not vary over the surface: the classic
// convention (no fall-off) or a directional light. Physically, the band is divided by pi like Lambert.
#include <rtlab/core/param_checks.hpp>
#include <rtlab/scene/plugin_abi.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <algorithm>
#include <cmath>

namespace {

using namespace rtlab;

class ToonMaterial final : public Material {
public:
    ToonMaterial(Whitted w, std::shared_ptr<const Texture> color, std::shared_ptr<const Texture> highlight, int levels,
                 float highlight_size, float outline)
        : Material(std::move(w)),
          m_color(std::move(color)),
          m_highlight(std::move(highlight)),
          m_levels(static_cast<float>(levels)),
          m_highlight_size(highlight_size),
          m_outline(outline) {}

    RGB direct(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, Convention c) const override {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return {};
        if (wo.z < m_outline) return {};
        const float band = std::min(std::ceil(wi.z * m_levels), m_levels) / m_levels;
        RGB out = t.diffuse * band;
        // The mirror direction of wi about the normal (0, 0, 1), against the viewer.
        const float alignment = -wi.x * wo.x - wi.y * wo.y + wi.z * wo.z;
        if (alignment > m_highlight_size) out += t.specular;
        return c == Convention::physical ? out * kInvPi : out;
    }

protected:
    void local_terms(const TextureLookup& q, SurfaceTerms& t) const override {
        t.diffuse = non_negative(m_color->eval(q));
        t.specular = non_negative(m_highlight->eval(q));
    }

private:
    // A texture may give anything; negative or NaN colours would poison the image.
    static RGB non_negative(const RGB& c) {
        auto f = [](float x) { return x > 0.0f ? x : 0.0f; };
        return {f(c.r), f(c.g), f(c.b)};
    }

    std::shared_ptr<const Texture> m_color, m_highlight;
    float m_levels, m_highlight_size, m_outline;
};

std::shared_ptr<Material> make_toon(const Params& p) {
    Material::Whitted w = read_whitted(p);
    auto color = texture_param(p, "color", RGB(0.8f));
    auto highlight = texture_param(p, "highlight", RGB(0.0f));
    const int levels = bounded_int(p, "levels", 3, 1, 16);
    const float size = float_in_range(p, "highlight_size", 0.97f, 0.0f, 0.999999f);
    const float outline = float_in_range(p, "outline", 0.0f, 0.0f, 0.999999f);
    return std::make_shared<ToonMaterial>(std::move(w), std::move(color), std::move(highlight), levels, size, outline);
}

TypeSpec toon_spec() {
    TypeSpec s("cel shading: n.l cut into flat bands, a hard-edged highlight and a dark outline");
    s.add("color", ParamKind::texture, "base colour").defaults("0.8");
    s.add("levels", ParamKind::integer, "lit bands").defaults("3").range(1, 16);
    s.add("highlight", ParamKind::texture, "added where the mirror direction is close to the viewer (0: none)")
        .defaults("0");
    s.add("highlight_size", ParamKind::number,
          "cosine between the mirror direction and the viewer above which the highlight shows")
        .defaults("0.97")
        .range(0, 0.999999);
    s.add("outline", ParamKind::number, "n.v below which the surface is black (0: none)")
        .defaults("0")
        .range(0, 0.999999);
    s.extend(material_shared_params(), "material");
    return s;
}

void register_types(rtlab::PluginRegistries& r) { r.materials.add("toon", make_toon, toon_spec()); }

}  // namespace

RTLAB_DEFINE_PLUGIN("toon: a cel-shading material", register_types)
