#pragma once
// Parameter helpers shared by the built-in materials and lights (private to the shading library).
//
// TEMPORARY: the checks and texture_param below stand in for rtlab/core/param_checks.hpp and
// rtlab/textures/texture_param.hpp (branch `params`); they go when that lands.
#include <rtlab/core/params.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/textures/texture.hpp>

#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>

namespace rtlab::shading_detail {

[[noreturn]] void fail_param(const Params& params, std::string_view name, const std::string& problem);
float positive_float(const Params& params, std::string_view name, float fallback, bool allow_zero = false);
float float_in_range(const Params& params, std::string_view name, float fallback, float lo, float hi);
int bounded_int(const Params& params, std::string_view name, int fallback, int lo, int hi);
RGB finite_rgb(const Params& params, std::string_view name, const RGB& fallback);
Vec3 finite_vec3(const Params& params, std::string_view name, const Vec3& fallback);

std::shared_ptr<const Texture> make_constant_texture(const RGB& colour);
/// The key `name` holds a colour (one number or three) or a Texture object; the fallback when absent.
std::shared_ptr<const Texture> texture_param(const Params& params, std::string_view name, const RGB& fallback);
/// Non-null when the texture is one colour everywhere, so per-hit lookups can be skipped.
const RGB* constant_of(const Texture& texture);
/// The opacity a texture gives at a lookup (its alpha).
float texture_alpha(const Texture& texture, const TextureLookup& lookup);

/// \brief A colour parameter: a constant (no virtual call per hit) or a texture.
class Channel {
public:
    Channel() = default;
    explicit Channel(std::shared_ptr<const Texture> texture);
    RGB eval(const TextureLookup& q) const { return m_texture ? m_texture->eval(q) : m_constant; }
    float alpha(const TextureLookup& q) const { return m_texture ? texture_alpha(*m_texture, q) : m_constant.g; }
    bool is_constant() const { return !m_texture; }
    const RGB& constant() const { return m_constant; }

private:
    std::shared_ptr<const Texture> m_texture;  // null for a constant
    RGB m_constant;
};

/// What a material type uses when the Whitted parameters are absent.
struct WhittedDefaults {
    RGB kr{0.0f}, kt{0.0f};
    float ior = 1.0f;
    bool fresnel = false;
};

/// Reads kr, kt, ior, ior_outside, fresnel, emission, opacity, absorption (every material's parameters).
/// Constant kr + kt > 1 (without Fresnel) or kr, kt > 1 (with it) are rejected.
Material::Whitted read_whitted(const Params& params, const WhittedDefaults& defaults);

/// The documentation of the Whitted parameters, appended to every material's doc string.
extern const char* const kWhittedDoc;

void register_lambert(MaterialRegistry& registry);
void register_phong(MaterialRegistry& registry);
void register_blinn_phong(MaterialRegistry& registry);
void register_mirror(MaterialRegistry& registry);
void register_glass(MaterialRegistry& registry);

void register_point(LightRegistry& registry);
void register_directional(LightRegistry& registry);
void register_spot(LightRegistry& registry);
void register_area(LightRegistry& registry);
void register_ambient(LightRegistry& registry);

}  // namespace rtlab::shading_detail
