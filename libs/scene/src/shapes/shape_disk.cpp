// Shape "disk": a flat disk or an annulus (rtlab/geometry/disk.hpp). uv: u from the inner to the outer edge,
// v the angle / 2 pi.
#include <rtlab/geometry/disk.hpp>

#include "shape_params.hpp"

namespace rtlab::scene_detail {

namespace {
TypeSpec disk_spec() {
    TypeSpec s("flat disk or annulus. uv: u from the inner to the outer edge, v the angle / 2 pi");
    s.add("center", ParamKind::vector, "the centre").defaults("[0, 0, 0]").in("world units");
    s.add("normal", ParamKind::vector, "its outside (non-zero)").defaults("[0, 1, 0]");
    s.add("radius", ParamKind::number, "the outer radius (> 0)").defaults("1").at_least(0).in("world units");
    s.add("inner_radius", ParamKind::number, "the hole's radius, less than radius (0: no hole)")
        .defaults("0")
        .at_least(0)
        .in("world units");
    return s;
}
}  // namespace

void register_disk(ShapeRegistry& registry) {
    registry.add(
        "disk",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 c = vec3_param(p, "center", Vec3(0.0f));
            const Vec3 n = vec3_param(p, "normal", Vec3(0.0f, 1.0f, 0.0f));
            const float radius = positive_float(p, "radius", 1.0f);
            const float inner = positive_float(p, "inner_radius", 0.0f, true);
            return build(p, [&] { return std::make_shared<Disk>(c, n, radius, inner); });
        },
        disk_spec());
}

}  // namespace rtlab::scene_detail
