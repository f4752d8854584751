#pragma once
// What the built-in shapes' factories share (private to the scene library): checked points and vectors, the
// wrapping of a geometry constructor's error, and one registration function per shape file.
#include <rtlab/core/error.hpp>
#include <rtlab/core/param_checks.hpp>
#include <rtlab/core/params.hpp>
#include <rtlab/scene/shape_registry.hpp>

#include <memory>
#include <string_view>

namespace rtlab::scene_detail {

/// A list of 3 finite numbers; the fallback when absent.
Vec3 vec3_param(const Params& p, std::string_view name, const Vec3& fallback);
/// A list of 3 finite numbers that must be given.
Vec3 required_vec3(const Params& p, std::string_view name);

/// Runs a geometry constructor, whose errors say what is wrong ("disk: radius must be positive"), and puts
/// the object's context ("shape 'disk'") in front of them.
template <class F>
std::shared_ptr<Shape> build(const Params& p, F&& f) {
    try {
        return f();
    } catch (const Error& e) {
        throw Error(p.context() + ": " + e.what());
    }
}

void register_sphere(ShapeRegistry& registry);
void register_disk(ShapeRegistry& registry);
void register_quad(ShapeRegistry& registry);
void register_box(ShapeRegistry& registry);
void register_cylinder(ShapeRegistry& registry);
void register_triangle(ShapeRegistry& registry);
void register_mesh(ShapeRegistry& registry);
void register_instance(ShapeRegistry& registry);

}  // namespace rtlab::scene_detail
