#include "builtin_params.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace rtlab::shading_detail {

std::string number_text(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

bool non_negative(const RGB& c) { return c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f; }

Vec3 finite_vec3(const Params& params, std::string_view name, const Vec3& fallback) {
    const Vec3 v = params.get_vec3(name, fallback);
    if (!is_finite(v)) fail_param(params, name, "must be finite");
    return v;
}

std::shared_ptr<const Texture> colour_param(const Params& params, std::string_view name, const RGB& fallback) {
    auto texture = texture_param(params, name, fallback);
    if (const RGB* c = texture->constant(); c && !non_negative(*c)) fail_param(params, name, "must be >= 0");
    return texture;
}

std::shared_ptr<const Texture> scalar_param(const Params& params, std::string_view name, float fallback, float lo,
                                            float hi) {
    auto texture = texture_param(params, name, fallback);
    if (const RGB* c = texture->constant(); c && !(scalar(*c) >= lo && scalar(*c) <= hi))
        fail_param(params, name,
                   "must be in [" + number_text(lo) + ", " + number_text(hi) + "], got " + number_text(scalar(*c)));
    return texture;
}

ColourChannel::ColourChannel(std::shared_ptr<const Texture> texture) {
    if (const RGB* c = texture->constant())
        m_constant = *c;
    else
        m_texture = std::move(texture);
}

RGB ColourChannel::sanitise(const RGB& c) {
    // NaN and negative give 0, +inf the largest float: finite and >= 0 whatever the texture gives.
    auto f = [](float x) { return x > 0.0f ? std::min(x, std::numeric_limits<float>::max()) : 0.0f; };
    return {f(c.r), f(c.g), f(c.b)};
}

ScalarChannel::ScalarChannel(std::shared_ptr<const Texture> texture, float lo, float hi, float nan_value)
    : m_lo(lo), m_hi(hi), m_nan(nan_value) {
    if (const RGB* c = texture->constant())
        m_constant = clamp(scalar(*c));
    else
        m_texture = std::move(texture);
}

float ScalarChannel::clamp(float x) const { return x == x ? std::clamp(x, m_lo, m_hi) : m_nan; }

MicrofacetModel read_microfacet_model(const Params& p) {
    return one_of(p, "distribution", "ggx", {"ggx", "beckmann"}) == "ggx" ? MicrofacetModel::ggx
                                                                          : MicrofacetModel::beckmann;
}

TypeSpec& with_material_params(TypeSpec& spec) { return spec.extend(material_shared_params(), "material"); }

TypeSpec with_material_params(TypeSpec&& spec) {
    spec.extend(material_shared_params(), "material");
    return std::move(spec);
}

TypeSpec lobe_spec(std::string doc, std::string exponent_doc) {
    TypeSpec s(std::move(doc));
    s.add("kd", ParamKind::texture, "diffuse colour").defaults("0.8");
    s.add("ks", ParamKind::texture, "specular colour").defaults("0.2");
    s.add("exponent", ParamKind::scalar, std::move(exponent_doc)).defaults("25").range(0, kMaxExponent);
    return with_material_params(std::move(s));
}

}  // namespace rtlab::shading_detail

namespace rtlab {

const std::vector<ParamSpec>& material_shared_params() {
    static const std::vector<ParamSpec> shared = [] {
        TypeSpec s("the Whitted terms");
        s.add("kr", ParamKind::texture,
              "mirror reflection; constant kr + kt must not exceed 1 (each 1 with fresnel), textured values are "
              "scaled down per hit")
            .defaults("0");
        s.add("kt", ParamKind::texture, "transmission through the surface, refracted by ior / ior_outside")
            .defaults("0");
        s.add("ior", ParamKind::number, "index of refraction inside (> 0; glass 1.5)").defaults("1").at_least(0.0);
        s.add("ior_outside", ParamKind::number, "index of refraction outside (> 0; a body in water 1.33)")
            .defaults("1")
            .at_least(0.0);
        s.add("fresnel", ParamKind::boolean, "weight kr by the Fresnel reflectance F and kt by 1 - F")
            .defaults("false");
        s.add("emission", ParamKind::texture, "light the surface gives off itself").defaults("0");
        s.add("emission_two_sided", ParamKind::boolean,
              "under direct and path, emission leaves both faces (else only the front, the outward normal's side)")
            .defaults("false");
        s.add("opacity", ParamKind::scalar,
              "cut-outs, shadow rays too: a texture's alpha when it has one, else its channel mean")
            .defaults("1")
            .range(0.0, 1.0);
        s.add("absorption", ParamKind::colour, "Beer-Lambert coefficient of the medium inside (0: clear)")
            .defaults("0")
            .in("per world unit");
        return s.params();
    }();
    return shared;
}

Material::Whitted read_whitted(const Params& p, const WhittedDefaults& d) {
    Material::Whitted w;
    w.kr = shading_detail::colour_param(p, "kr", d.kr);
    w.kt = shading_detail::colour_param(p, "kt", d.kt);
    w.emission = shading_detail::colour_param(p, "emission", RGB(0.0f));
    w.opacity = shading_detail::scalar_param(p, "opacity", 1.0f, 0.0f, 1.0f);
    w.ior_inside = positive_float(p, "ior", d.ior);
    w.ior_outside = positive_float(p, "ior_outside", 1.0f);
    w.fresnel = p.get_bool("fresnel", d.fresnel);
    w.emission_two_sided = p.get_bool("emission_two_sided", false);
    w.absorption = finite_rgb(p, "absorption", RGB(0.0f));
    if (!shading_detail::non_negative(w.absorption)) fail_param(p, "absorption", "must be >= 0");

    const RGB *kr = w.kr->constant(), *kt = w.kt->constant();
    auto check_range = [&](const RGB* c, const char* name) {
        if (c && w.fresnel && c->max_component() > 1.0f) fail_param(p, name, "must be <= 1 with fresnel");
    };
    check_range(kr, "kr");
    check_range(kt, "kt");
    if (kr && kt && !w.fresnel && (*kr + *kt).max_component() > 1.0f)
        fail_param(p, "kr",
                   "plus kt exceeds 1 (" + shading_detail::number_text((*kr + *kt).max_component()) +
                       "); lower them or set fresnel to weight them");
    return w;
}

}  // namespace rtlab
