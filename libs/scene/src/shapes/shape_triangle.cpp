// Shape "triangle": one triangle by its corners (a mesh of one, rtlab/geometry/triangle_shape.hpp).
#include <rtlab/geometry/triangle_shape.hpp>

#include "shape_params.hpp"

namespace rtlab::scene_detail {

namespace {
TypeSpec triangle_spec() {
    TypeSpec s("one triangle; outside is the side of (p1 - p0) x (p2 - p0)");
    s.add("p0", ParamKind::vector, "the first corner").require().in("world units");
    s.add("p1", ParamKind::vector, "the second corner").require().in("world units");
    s.add("p2", ParamKind::vector, "the third corner, not on the line through the first two")
        .require()
        .in("world units");
    return s;
}
}  // namespace

void register_triangle(ShapeRegistry& registry) {
    registry.add(
        "triangle",
        [](const Params& p) -> std::shared_ptr<Shape> {
            auto mesh = std::make_shared<TriangleMesh>();
            mesh->positions = {required_vec3(p, "p0"), required_vec3(p, "p1"), required_vec3(p, "p2")};
            mesh->triangles = {{0u, 1u, 2u}};
            if (mesh->is_degenerate(0)) throw Error(p.context() + ": the three corners are collinear or repeated");
            return std::make_shared<TriangleShape>(std::move(mesh), 0u);
        },
        triangle_spec());
}

}  // namespace rtlab::scene_detail
