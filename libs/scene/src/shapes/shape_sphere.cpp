// Shape "sphere": a centre and a radius (rtlab/geometry/sphere.hpp). uv: longitude, latitude (v = 1 at +y).
#include <rtlab/geometry/sphere.hpp>

#include "shape_params.hpp"

namespace rtlab::scene_detail {

namespace {
TypeSpec sphere_spec() {
    TypeSpec s("sphere. uv: u the longitude (0 at -x, growing towards -z), v the latitude (1 at +y)");
    s.add("center", ParamKind::vector, "the centre").defaults("[0, 0, 0]").in("world units");
    s.add("radius", ParamKind::number, "the radius (> 0)").defaults("1").at_least(0).in("world units");
    return s;
}
}  // namespace

void register_sphere(ShapeRegistry& registry) {
    registry.add(
        "sphere",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 c = vec3_param(p, "center", Vec3(0.0f));
            const float radius = positive_float(p, "radius", 1.0f);
            return build(p, [&] { return std::make_shared<Sphere>(c, radius); });
        },
        sphere_spec());
}

}  // namespace rtlab::scene_detail
