// The built-in shapes, one file each under shapes/ (its factory and its declaration), registered in one place.
#include <rtlab/scene/shape_registry.hpp>

#include "shapes/shape_params.hpp"

namespace rtlab {

void register_builtins(ShapeRegistry& registry) {
    scene_detail::register_sphere(registry);
    scene_detail::register_disk(registry);
    scene_detail::register_quad(registry);
    scene_detail::register_box(registry);
    scene_detail::register_cylinder(registry);
    scene_detail::register_triangle(registry);
    scene_detail::register_mesh(registry);
    scene_detail::register_instance(registry);
}

ShapeRegistry make_shape_registry() {
    ShapeRegistry registry("shape");
    register_builtins(registry);
    return registry;
}

}  // namespace rtlab
