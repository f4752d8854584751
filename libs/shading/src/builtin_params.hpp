#pragma once
// What the built-in materials and lights share (private to the shading library): colour and scalar
// parameters that hold a constant or a texture, the Whitted terms every material reads, and the
// registration functions. The checked reads themselves are core's (rtlab/core/param_checks.hpp) and the
// "constant or texture" convention is the textures library's (rtlab/textures/texture_param.hpp).
#include <rtlab/core/param_checks.hpp>
#include <rtlab/core/params.hpp>
#include <rtlab/shading/brdf.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/textures/texture.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <memory>
#include <string>
#include <string_view>

namespace rtlab::shading_detail {

/// The shortest text of v that a message shows ("1.5").
std::string number_text(double v);
/// Whether every component is >= 0 (NaN is not).
bool non_negative(const RGB& c);

/// A point or vector with finite components (core's checks have no Vec3 read).
Vec3 finite_vec3(const Params& params, std::string_view name, const Vec3& fallback);

/// A colour parameter (kd, albedo, rd...): texture_param, and a constant must be >= 0.
std::shared_ptr<const Texture> colour_param(const Params& params, std::string_view name, const RGB& fallback);
/// A scalar parameter (exponent, roughness, nu...): texture_param with the scalar rule of texture_param.hpp
/// (channel mean), and a constant must lie in [lo, hi].
std::shared_ptr<const Texture> scalar_param(const Params& params, std::string_view name, float fallback, float lo,
                                            float hi);

/// \brief A colour parameter at a hit: a constant read once (Texture::constant(), no virtual call per hit)
/// or a texture, whose values are kept finite and >= 0 (a texture may give anything; the BRDFs reject
/// negative or non-finite colours).
class ColourChannel {
public:
    explicit ColourChannel(std::shared_ptr<const Texture> texture);
    RGB eval(const TextureLookup& q) const { return m_texture ? sanitise(m_texture->eval(q)) : m_constant; }
    bool is_constant() const { return !m_texture; }

private:
    static RGB sanitise(const RGB& c);
    std::shared_ptr<const Texture> m_texture;  // null for a constant
    RGB m_constant;
};

/// \brief A scalar parameter at a hit: scalar() of the texture's colour, clamped to [lo, hi]; NaN gives
/// `nan_value`. A constant is read once.
class ScalarChannel {
public:
    ScalarChannel(std::shared_ptr<const Texture> texture, float lo, float hi, float nan_value);
    float eval(const TextureLookup& q) const { return m_texture ? clamp(scalar(m_texture->eval(q))) : m_constant; }
    bool is_constant() const { return !m_texture; }

private:
    float clamp(float x) const;
    std::shared_ptr<const Texture> m_texture;  // null for a constant
    float m_constant = 0.0f, m_lo, m_hi, m_nan;
};

/// The largest specular exponent (Phong, Blinn-Phong, Ashikhmin-Shirley): the BRDFs need a finite one,
/// Ashikhmin-Shirley's sqrt((nu + 1)(nv + 1)) must not overflow a float, and beyond ~1e7 a float lobe is a
/// mirror anyway.
inline constexpr float kMaxExponent = 1e15f;

/// Appends the keys every material shares (material_shared_params()) to a material type's declaration.
TypeSpec& with_material_params(TypeSpec& spec);
TypeSpec with_material_params(TypeSpec&& spec);
/// The declaration of a diffuse plus specular-lobe material (phong, blinn-phong): kd, ks and exponent.
TypeSpec lobe_spec(std::string doc, std::string exponent_doc);

/// The Whitted defaults of a dielectric model: ior 1.5, kr and kt 0 (its own lobes reflect and refract).
inline WhittedDefaults glass_defaults() {
    WhittedDefaults d;
    d.ior = 1.5f;
    return d;
}

/// The "distribution" parameter of the microfacet models: ggx (default) or beckmann.
MicrofacetModel read_microfacet_model(const Params& params);

void register_lambert(MaterialRegistry& registry);
void register_phong(MaterialRegistry& registry);
void register_blinn_phong(MaterialRegistry& registry);
void register_cook_torrance(MaterialRegistry& registry);
void register_ashikhmin_shirley(MaterialRegistry& registry);
void register_mirror(MaterialRegistry& registry);
void register_glass(MaterialRegistry& registry);
void register_rough_dielectric(MaterialRegistry& registry);

void register_point(LightRegistry& registry);
void register_directional(LightRegistry& registry);
void register_spot(LightRegistry& registry);
void register_area(LightRegistry& registry);
void register_ambient(LightRegistry& registry);

}  // namespace rtlab::shading_detail
