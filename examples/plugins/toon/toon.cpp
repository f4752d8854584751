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
//
// Under the sampling integrators (direct, path: docs/sampled-materials.md) the material is what the cartoon
// stands for, a physical BRDF that conserves energy, and the bands, the outline and the flat highlight are
// left to the whitted integrator (direct()). Bands are a remapping of n.l for one light at a time: light that
// arrives from every direction at once has no n.l to quantise, and a BRDF of band / (pi n.l) would reflect up
// to `levels` times what it receives at grazing light. An outline that depends on the viewer alone would not
// be reciprocal. So the sampled lobes are:
//   diffuse    color / pi (Lambert), sampled by the cosine;
//   highlight  a cone about the mirror direction of wo, the same cone in which direct() draws the highlight:
//              with x = (cos a - s) / (1 - s), a the angle between wi and the mirror direction and s =
//              highlight_size, f = highlight x / (pi (1 - s)) where x > 0 and 0 outside, sampled in proportion to
//              it (1 - cos a = (1 - s)(1 - sqrt(u))). It reflects a light as a spot as wide as the whitted
//              highlight, brightest at its centre and fading to nothing at the cone's rim; it is reciprocal (x is
//              symmetric in wo and wi) and reflects at most `highlight` (its pdf integrates to 1 over the cone,
//              and the cosine is at most 1). A cone of constant value (a hard rim, the whitted look) would be as
//              physical, but a density that jumps costs the chi-square check's quadrature (bsdf_check.hpp)
//              about fifty times as much to integrate to the accuracy its test needs.
// Energy: the two lobes reflect at most color + highlight, so where that exceeds 1 the sampled diffuse part
// is lowered to 1 - highlight (highlight itself capped at 1); the whitted look keeps the colours as given.
#include <rtlab/core/frame.hpp>
#include <rtlab/core/param_checks.hpp>
#include <rtlab/scene/plugin_abi.hpp>
#include <rtlab/shading/bsdf.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

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
          m_outline(outline),
          m_cone_width(1.0f - highlight_size),
          m_cone_peak(1.0f / (kPi * m_cone_width)) {}

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
    // The sampled lobes (see the top of the file). Material hands them wo and wi above the surface (mirrored
    // when the viewer is below: the toon is two-sided) and adds kr, kt and opacity around them.
    bool has_lobes() const override { return true; }

    RGB lobe_eval(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, TransportMode) const override {
        const Lobes l = lobes(t);
        return l.diffuse * kInvPi + l.highlight * cone_density(wo, wi);
    }

    float lobe_pdf(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, TransportMode) const override {
        const Lobes l = lobes(t);
        return l.diffuse_chance * wi.z * kInvPi + (1.0f - l.diffuse_chance) * cone_density(wo, wi);
    }

    std::optional<LobeDraw> lobe_sample(const SurfaceTerms& t, const Vec3& wo, float uc, const Vec2& u,
                                        TransportMode) const override {
        if (uc < lobes(t).diffuse_chance) return LobeDraw{sample_cosine_hemisphere(u), kLobeDiffuse | kLobeReflection};
        // x = sqrt(u.x) (its density is 2 x), 1 - cos = (1 - highlight_size)(1 - x): written with 1 - cos itself,
        // so that a cone of highlight_size 0.999999 keeps its angles in float.
        const float one_minus_cos = (1.0f - std::sqrt(u.x)) * m_cone_width;
        const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
        const float phi = 2.0f * kPi * u.y;
        const Vec3 local(sin_theta * std::cos(phi), sin_theta * std::sin(phi), 1.0f - one_minus_cos);
        const Vec3 wi = glm::normalize(Frame::from_normal(mirror(wo)).to_world(local));
        if (!(wi.z > 0.0f)) return std::nullopt;  // the part of the cone below the horizon is lost
        return LobeDraw{wi, kLobeGlossy | kLobeReflection};
    }

    void local_terms(const TextureLookup& q, SurfaceTerms& t) const override {
        t.diffuse = non_negative(m_color->eval(q));
        t.specular = non_negative(m_highlight->eval(q));
    }

private:
    /// The sampled lobes' reflectances at one hit, kept to a total of at most 1, and the chance of drawing from
    /// the diffuse one (in proportion to the channel means).
    struct Lobes {
        RGB diffuse, highlight;
        float diffuse_chance = 1.0f;
    };
    static Lobes lobes(const SurfaceTerms& t) {
        Lobes l;
        const auto capped = [](float colour, float highlight) { return std::min(colour, 1.0f - highlight); };
        l.highlight = {std::min(t.specular.r, 1.0f), std::min(t.specular.g, 1.0f), std::min(t.specular.b, 1.0f)};
        l.diffuse = {capped(t.diffuse.r, l.highlight.r), capped(t.diffuse.g, l.highlight.g),
                     capped(t.diffuse.b, l.highlight.b)};
        const float d = channel_mean(l.diffuse), h = channel_mean(l.highlight);
        l.diffuse_chance = d + h > 0.0f ? d / (d + h) : 1.0f;
        return l;
    }

    static Vec3 mirror(const Vec3& w) { return {-w.x, -w.y, w.z}; }

    /// The highlight lobe's density over solid angle: x / (pi (1 - highlight_size)), x = 1 - (1 - cos a) /
    /// (1 - highlight_size) > 0 within the cone, 0 outside. 1 - cos a is half the squared chord between wi and the
    /// mirror direction of wo: exact in float for small cones, where a dot product would round it away, and the
    /// same with wo and wi swapped.
    float cone_density(const Vec3& wo, const Vec3& wi) const {
        const Vec3 d = mirror(wo) - wi;
        const float x = 1.0f - 0.5f * glm::dot(d, d) / m_cone_width;
        return x > 0.0f ? x * m_cone_peak : 0.0f;
    }

    // A texture may give anything; negative or NaN colours would poison the image.
    static RGB non_negative(const RGB& c) {
        auto f = [](float x) { return x > 0.0f ? x : 0.0f; };
        return {f(c.r), f(c.g), f(c.b)};
    }

    std::shared_ptr<const Texture> m_color, m_highlight;
    float m_levels, m_highlight_size, m_outline;
    float m_cone_width;  // 1 - highlight_size: the cone's 1 - cos(half-angle)
    float m_cone_peak;   // the highlight lobe's density on its axis, 1 / (pi (1 - highlight_size))
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
    TypeSpec s(
        "cel shading: n.l cut into flat bands, a hard-edged highlight and a dark outline (whitted); Lambert and a "
        "glossy cone (direct, path)");
    s.add("color", ParamKind::texture, "base colour").defaults("0.8");
    s.add("levels", ParamKind::integer, "lit bands").defaults("3").range(1, 16);
    s.add("highlight", ParamKind::texture,
          "added where the mirror direction is close to the viewer (0: none); direct, path: the cone's reflectance")
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
