#include <rtlab/textures/texture.hpp>

#include "texture_params.hpp"

namespace rtlab {

void register_builtins(TextureRegistry& registry) {
    detail::register_solid(registry);
    detail::register_checker(registry);
    detail::register_checker3d(registry);
    detail::register_mandelbrot(registry);
    detail::register_perlin(registry);
    detail::register_simplex(registry);
    detail::register_image(registry);
    detail::register_cubemap(registry);
    detail::register_stars(registry);
}

TextureRegistry make_texture_registry() {
    TextureRegistry registry("texture");
    register_builtins(registry);
    return registry;
}

}  // namespace rtlab
