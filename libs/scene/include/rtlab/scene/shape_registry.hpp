#pragma once
/// \brief Shapes created by name, like textures, materials and lights: what a scene file's `shapes` use.
#include <rtlab/core/registry.hpp>
#include <rtlab/geometry/shape.hpp>

namespace rtlab {

using ShapeRegistry = Registry<Shape>;

/// Registers sphere, disk (with an optional inner radius), quad, box, cylinder, triangle, mesh (a PLY or OBJ
/// file with its own kd-tree) and instance (a named shape under a 4x4 matrix), each with the declaration of its
/// parameters (spec()). File names ("filename") must already be resolved: the factories open them as given.
void register_builtins(ShapeRegistry& registry);

/// A registry with category "shape" and every built-in registered.
ShapeRegistry make_shape_registry();

}  // namespace rtlab
