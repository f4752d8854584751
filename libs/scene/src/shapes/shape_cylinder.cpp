// Shape "cylinder": a finite cylinder between two points, with or without caps (rtlab/geometry/cylinder.hpp).
#include <rtlab/geometry/cylinder.hpp>

#include "shape_params.hpp"

namespace rtlab::scene_detail {

namespace {
TypeSpec cylinder_spec() {
    TypeSpec s("finite cylinder round the axis from base to top");
    s.add("base", ParamKind::vector, "the centre of one end").defaults("[0, 0, 0]").in("world units");
    s.add("top", ParamKind::vector, "the centre of the other end, not base").defaults("[0, 1, 0]").in("world units");
    s.add("radius", ParamKind::number, "the radius (> 0)").defaults("1").at_least(0).in("world units");
    s.add("caps", ParamKind::boolean, "closed ends").defaults("true");
    return s;
}
}  // namespace

void register_cylinder(ShapeRegistry& registry) {
    registry.add(
        "cylinder",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 base = vec3_param(p, "base", Vec3(0.0f)), top = vec3_param(p, "top", Vec3(0.0f, 1.0f, 0.0f));
            const float radius = positive_float(p, "radius", 1.0f);
            const bool caps = p.get_bool("caps", true);
            if (base == top) fail_param(p, "top", "must differ from 'base'");
            return build(p, [&] { return std::make_shared<Cylinder>(base, top, radius, caps); });
        },
        cylinder_spec());
}

}  // namespace rtlab::scene_detail
