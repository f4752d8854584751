#include "shading_params.hpp"

#include <rtlab/core/error.hpp>

#include <cmath>
#include <sstream>

namespace rtlab::shading_detail {

namespace {
std::string number_text(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

class ConstantTexture final : public Texture {
public:
    explicit ConstantTexture(const RGB& c) : m_colour(c) {}
    RGB eval(const TextureLookup&) const override { return m_colour; }
    const RGB& colour() const { return m_colour; }

private:
    RGB m_colour;
};
}  // namespace

void fail_param(const Params& params, std::string_view name, const std::string& problem) {
    throw Error(params.context() + ": parameter '" + std::string(name) + "' " + problem);
}

float positive_float(const Params& params, std::string_view name, float fallback, bool allow_zero) {
    const float v = params.get_float(name, fallback);
    const bool ok = std::isfinite(v) && (allow_zero ? v >= 0.0f : v > 0.0f);
    if (!ok)
        fail_param(params, name,
                   std::string("must be finite and ") + (allow_zero ? ">= 0" : "> 0") + ", got " + number_text(v));
    return v;
}

float float_in_range(const Params& params, std::string_view name, float fallback, float lo, float hi) {
    const float v = params.get_float(name, fallback);
    if (!(v >= lo && v <= hi))
        fail_param(params, name,
                   "must be in [" + number_text(lo) + ", " + number_text(hi) + "], got " + number_text(v));
    return v;
}

int bounded_int(const Params& params, std::string_view name, int fallback, int lo, int hi) {
    const int v = params.get_int(name, fallback);
    if (v < lo || v > hi)
        fail_param(params, name,
                   "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + std::to_string(v));
    return v;
}

RGB finite_rgb(const Params& params, std::string_view name, const RGB& fallback) {
    const RGB c = params.get_rgb(name, fallback);
    if (!c.is_finite()) fail_param(params, name, "must be finite");
    return c;
}

Vec3 finite_vec3(const Params& params, std::string_view name, const Vec3& fallback) {
    const Vec3 v = params.get_vec3(name, fallback);
    if (!is_finite(v)) fail_param(params, name, "must be finite");
    return v;
}

std::shared_ptr<const Texture> make_constant_texture(const RGB& colour) {
    return std::make_shared<ConstantTexture>(colour);
}

std::shared_ptr<const Texture> texture_param(const Params& params, std::string_view name, const RGB& fallback) {
    if (!params.has(name)) return make_constant_texture(fallback);
    // Params cannot say what a value holds without reading it: try the object first.
    try {
        if (auto t = params.get_object<Texture>(name)) return t;
    } catch (const Error&) {
    }
    const RGB c = finite_rgb(params, name, fallback);
    return make_constant_texture(c);
}

const RGB* constant_of(const Texture& texture) {
    const auto* c = dynamic_cast<const ConstantTexture*>(&texture);
    return c ? &c->colour() : nullptr;
}

float texture_alpha(const Texture& texture, const TextureLookup& lookup) { return texture.eval(lookup).g; }

Channel::Channel(std::shared_ptr<const Texture> texture) {
    if (!texture) return;
    if (const RGB* c = constant_of(*texture))
        m_constant = *c;
    else
        m_texture = std::move(texture);
}

const char* const kWhittedDoc =
    " Whitted terms (all materials): kr mirror reflection, kt transmission (colours or textures); ior index "
    "inside (default 1, glass 1.5), ior_outside (default 1); fresnel: weight kr by F and kt by 1 - F; "
    "emission colour or texture (default 0); opacity number or texture alpha (default 1; cut-outs, shadow "
    "rays too); absorption: Beer-Lambert coefficient per unit distance inside (default 0). Constant kr + kt "
    "> 1 (each > 1 with fresnel) is an error; textured values are scaled down per hit.";

Material::Whitted read_whitted(const Params& p, const WhittedDefaults& d) {
    Material::Whitted w;
    w.kr = texture_param(p, "kr", d.kr);
    w.kt = texture_param(p, "kt", d.kt);
    w.emission = texture_param(p, "emission", RGB(0.0f));
    w.opacity = texture_param(p, "opacity", RGB(1.0f));
    w.ior_inside = positive_float(p, "ior", d.ior);
    w.ior_outside = positive_float(p, "ior_outside", 1.0f);
    w.fresnel = p.get_bool("fresnel", d.fresnel);
    w.absorption = finite_rgb(p, "absorption", RGB(0.0f));
    if (w.absorption.r < 0.0f || w.absorption.g < 0.0f || w.absorption.b < 0.0f)
        fail_param(p, "absorption", "must be >= 0");

    const RGB *kr = constant_of(*w.kr), *kt = constant_of(*w.kt);
    auto check_range = [&](const RGB* c, const char* name) {
        if (c && (c->r < 0.0f || c->g < 0.0f || c->b < 0.0f)) fail_param(p, name, "must be >= 0");
        if (c && w.fresnel && c->max_component() > 1.0f) fail_param(p, name, "must be <= 1 with fresnel");
    };
    check_range(kr, "kr");
    check_range(kt, "kt");
    if (kr && kt && !w.fresnel && (*kr + *kt).max_component() > 1.0f)
        fail_param(p, "kr",
                   "plus kt exceeds 1 (" + number_text((*kr + *kt).max_component()) +
                       "); lower them or set fresnel to weight them");
    if (const RGB* o = constant_of(*w.opacity); o && !(o->g >= 0.0f && o->g <= 1.0f))
        fail_param(p, "opacity", "must be in [0, 1]");
    return w;
}

}  // namespace rtlab::shading_detail
