// Shape "instance": another copy of a named shape under a 4x4 matrix (rtlab/geometry/instance.hpp); a mesh's
// copies share its tree.
#include <rtlab/geometry/instance.hpp>

#include "shape_params.hpp"

#include <string>

namespace rtlab::scene_detail {

namespace {
TypeSpec instance_spec() {
    TypeSpec s(
        "another copy of a named shape (usually a mesh, whose tree it shares) with its own transform and "
        "material");
    s.add("shape", ParamKind::shape, "the name of the shape to show again").require();
    s.add("matrix", ParamKind::numbers,
          "object to world, 16 numbers row by row (default: the identity; a scene file gives 'transform')");
    return s;
}

Mat4 matrix_param(const Params& p) {
    if (!p.has("matrix")) return Mat4(1.0f);
    const Params::List l = p.get_list("matrix");
    if (l.size() != 16) fail_param(p, "matrix", "must be 16 numbers (row by row), not " + std::to_string(l.size()));
    Mat4 m(1.0f);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) m[col][row] = static_cast<float>(l[static_cast<std::size_t>(row * 4 + col)]);
    return m;
}
}  // namespace

void register_instance(ShapeRegistry& registry) {
    registry.add(
        "instance",
        [](const Params& p) -> std::shared_ptr<Shape> {
            auto shape = p.get_object<const Shape>("shape");
            if (!shape) fail_param(p, "shape", "is missing: name the shape to show again");
            const Mat4 m = matrix_param(p);
            return build(p, [&] { return std::make_shared<Instance>(std::move(shape), m); });
        },
        instance_spec());
}

}  // namespace rtlab::scene_detail
