#pragma once
// Parameter helpers only the built-in textures need; the general checks are in rtlab/core/param_checks.hpp.
#include <rtlab/core/image.hpp>
#include <rtlab/core/param_checks.hpp>
#include <rtlab/textures/texture.hpp>

#include <memory>
#include <string>
#include <string_view>

namespace rtlab::detail {

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
