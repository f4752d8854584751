#pragma once
// Parameter helpers only the built-in textures need; the general checks are in rtlab/core/param_checks.hpp.
#include <rtlab/core/image.hpp>
#include <rtlab/core/param_checks.hpp>
#include <rtlab/textures/texture.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <memory>
#include <string>
#include <string_view>

namespace rtlab::detail {

/// ColorEncoding from "srgb" or "linear".
ColorEncoding get_encoding(const Params& params);

/// Declares `encoding` (what get_encoding reads).
void add_encoding(TypeSpec& spec);
/// Declares color1 and color2, each a colour or a texture, with what each stands for and its default.
void add_two_colours(TypeSpec& spec, const std::string& what1, const std::string& default1, const std::string& what2,
                     const std::string& default2);
/// Declares what image and cubemap share besides their files: encoding, intensity, lod, bake and bake_size
/// (whose default is `bake_size`).
void add_image_options(TypeSpec& spec, const std::string& bake_size_doc, const std::string& bake_size);

/// A texture that is one colour everywhere (what "solid" creates and make_constant_texture returns).
std::shared_ptr<Texture> make_solid(const RGB& colour);

/// Registration hooks, one per texture file.
void register_solid(TextureRegistry& registry);
void register_checker(TextureRegistry& registry);
void register_checker3d(TextureRegistry& registry);
void register_mandelbrot(TextureRegistry& registry);
void register_perlin(TextureRegistry& registry);
void register_simplex(TextureRegistry& registry);
void register_image(TextureRegistry& registry);
void register_cubemap(TextureRegistry& registry);
void register_stars(TextureRegistry& registry);

}  // namespace rtlab::detail
