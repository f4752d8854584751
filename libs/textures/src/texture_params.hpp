#pragma once
// Parameter helpers shared by the built-in textures: checked numbers, uv pairs, colour-or-texture.
#include <rtlab/core/image.hpp>
#include <rtlab/core/params.hpp>
#include <rtlab/textures/texture.hpp>

#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>

namespace rtlab::detail {

/// Throws rtlab::Error "<context>: parameter '<name>' <problem>".
[[noreturn]] void fail_param(const Params& params, std::string_view name, const std::string& problem);

/// A finite number > 0 (or >= 0 when allow_zero).
float positive_float(const Params& params, std::string_view name, float fallback, bool allow_zero = false);
/// An integer in [lo, hi].
int bounded_int(const Params& params, std::string_view name, int fallback, int lo, int hi);
/// One number (both components) or a list of two numbers, all finite.
Vec2 get_vec2(const Params& params, std::string_view name, Vec2 fallback);
/// One of the given words.
std::string one_of(const Params& params, std::string_view name, std::string_view fallback,
                   std::initializer_list<std::string_view> allowed);
/// A colour with finite components.
RGB finite_rgb(const Params& params, std::string_view name, const RGB& fallback);
/// ColorEncoding from "srgb" or "linear".
ColorEncoding get_encoding(const Params& params);

/// A texture that is one colour everywhere (what "solid" creates).
std::shared_ptr<const Texture> make_constant(const RGB& colour);

/// The colour parameter `colour_name` or the nested texture `texture_name` (not both); the fallback colour
/// when neither is given.
std::shared_ptr<const Texture> colour_or_texture(const Params& params, std::string_view colour_name,
                                                 std::string_view texture_name, const RGB& fallback);

/// Registration hooks, one per texture file.
void register_solid(TextureRegistry& registry);
void register_checker(TextureRegistry& registry);
void register_checker3d(TextureRegistry& registry);
void register_mandelbrot(TextureRegistry& registry);
void register_perlin(TextureRegistry& registry);
void register_simplex(TextureRegistry& registry);
void register_image(TextureRegistry& registry);
void register_cubemap(TextureRegistry& registry);

}  // namespace rtlab::detail
