#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>

#include "builtin_params.hpp"

namespace rtlab {

void register_builtins(MaterialRegistry& registry) {
    shading_detail::register_lambert(registry);
    shading_detail::register_phong(registry);
    shading_detail::register_blinn_phong(registry);
    shading_detail::register_cook_torrance(registry);
    shading_detail::register_ashikhmin_shirley(registry);
    shading_detail::register_mirror(registry);
    shading_detail::register_glass(registry);
    shading_detail::register_rough_dielectric(registry);
}

MaterialRegistry make_material_registry() {
    MaterialRegistry registry("material");
    register_builtins(registry);
    return registry;
}

void register_builtins(LightRegistry& registry) {
    shading_detail::register_point(registry);
    shading_detail::register_directional(registry);
    shading_detail::register_spot(registry);
    shading_detail::register_area(registry);
    shading_detail::register_ambient(registry);
}

LightRegistry make_light_registry() {
    LightRegistry registry("light");
    register_builtins(registry);
    return registry;
}

}  // namespace rtlab
