#pragma once
/// \brief "A constant or a texture": reading a parameter that may vary over a surface from one key.
///
/// The convention for every such parameter (a checker's tile colours, a material's albedo, roughness or
/// opacity): ONE key holding either a constant, one number (grey) or a list of 3 numbers, or a texture
/// object stored with params.set_object<Texture>(name, texture). A scene file puts a texture's name or an
/// inline texture under the same key; the loader resolves it to the object. Never two keys (no
/// "color" beside "color_texture").
///
/// Scalars from a texture (roughness, metallic, a bump height) are scalar(texture.eval(lookup)): the mean
/// of the three channels, so a grey constant or a grey image gives its own value exactly.
///
/// Opacity (cut-outs) is opacity(texture, lookup): the texture's alpha when it has one (an RGBA or
/// grey + alpha image file), else the scalar of its colour. So the same RGBA image can be both a
/// material's colour and its opacity (Saturn's rings: colour from RGB, holes from alpha), and a grey
/// mask image or a constant such as 0.5 works as well.
#include <rtlab/core/color.hpp>
#include <rtlab/core/params.hpp>
#include <rtlab/textures/texture.hpp>

#include <memory>
#include <string_view>

namespace rtlab {

/// A texture that is `colour` everywhere; its constant() returns that colour.
std::shared_ptr<const Texture> make_constant_texture(const RGB& colour);

/// The parameter `name` as a texture: a texture object as given, a constant (one number or a list of 3,
/// all finite) as make_constant_texture, and make_constant_texture(fallback) when the key is absent.
/// Anything else throws rtlab::Error naming the parameter.
std::shared_ptr<const Texture> texture_param(const Params& params, std::string_view name, const RGB& fallback);
/// The same with a grey fallback, for scalar parameters such as roughness.
std::shared_ptr<const Texture> texture_param(const Params& params, std::string_view name, float fallback);

/// The scalar a colour stands for: the mean of its channels. Computed in double, so that scalar(RGB(x))
/// == x for every finite float x.
inline float scalar(const RGB& c) {
    return static_cast<float>((static_cast<double>(c.r) + static_cast<double>(c.g) + static_cast<double>(c.b)) / 3.0);
}

/// The opacity a texture gives at a lookup: alpha(lookup) when has_alpha(), else scalar(eval(lookup)).
inline float opacity(const Texture& texture, const TextureLookup& lookup) {
    return texture.has_alpha() ? texture.alpha(lookup) : scalar(texture.eval(lookup));
}

}  // namespace rtlab
