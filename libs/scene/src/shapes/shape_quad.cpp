// Shape "quad": the parallelogram corner + a edge_u + b edge_v, a, b in [0, 1] (rtlab/geometry/quad.hpp).
#include <rtlab/geometry/quad.hpp>

#include "shape_params.hpp"

namespace rtlab::scene_detail {

namespace {
TypeSpec quad_spec() {
    TypeSpec s(
        "parallelogram corner + a edge_u + b edge_v, a, b in [0, 1]; outside is the side of edge_u x "
        "edge_v; uv = (a, b)");
    s.add("corner", ParamKind::vector, "one corner").require().in("world units");
    s.add("edge_u", ParamKind::vector, "the edge along which u grows").require().in("world units");
    s.add("edge_v", ParamKind::vector, "the edge along which v grows, not parallel to edge_u")
        .require()
        .in("world units");
    return s;
}
}  // namespace

void register_quad(ShapeRegistry& registry) {
    registry.add(
        "quad",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 corner = required_vec3(p, "corner"), u = required_vec3(p, "edge_u"),
                       v = required_vec3(p, "edge_v");
            return build(p, [&] { return std::make_shared<Quad>(corner, u, v); });
        },
        quad_spec());
}

}  // namespace rtlab::scene_detail
