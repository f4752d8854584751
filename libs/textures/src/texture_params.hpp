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
