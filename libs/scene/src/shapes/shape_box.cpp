// Shape "box": an axis-aligned solid box between two corners (rtlab/geometry/box.hpp).
#include <rtlab/geometry/box.hpp>

#include "shape_params.hpp"

namespace rtlab::scene_detail {

namespace {
TypeSpec box_spec() {
    TypeSpec s("axis-aligned solid box");
    s.add("min", ParamKind::vector, "the corner with the smallest coordinates").require().in("world units");
    s.add("max", ParamKind::vector, "the opposite corner, larger on every axis").require().in("world units");
    return s;
}
}  // namespace

void register_box(ShapeRegistry& registry) {
    registry.add(
        "box",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 lo = required_vec3(p, "min"), hi = required_vec3(p, "max");
            if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) fail_param(p, "max", "must exceed 'min' on every axis");
            return build(p, [&] { return std::make_shared<Box>(AABB{lo, hi}); });
        },
        box_spec());
}

}  // namespace rtlab::scene_detail
