// Shape "mesh": a PLY or OBJ file's triangles with their own acceleration structure (rtlab/accel/mesh_shape.hpp),
// optionally scaled to stand on the floor.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/geometry/fit_on_floor.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/mesh_io.hpp>
#include <rtlab/geometry/smooth_normals.hpp>

#include "shape_params.hpp"

#include <algorithm>
#include <string>

namespace rtlab::scene_detail {

namespace {
TypeSpec mesh_spec() {
    TypeSpec s("triangle mesh from a PLY or OBJ file, with its own acceleration structure");
    s.add("filename", ParamKind::file, "the PLY or OBJ file").require();
    s.add("accel", ParamKind::word, "the acceleration structure").defaults("kd-sah").allow(accelerator_methods());
    s.add("smooth_normals", ParamKind::boolean, "area-weighted vertex normals when the file has none")
        .defaults("false");
    s.add("fit", ParamKind::number,
          "scaled so that its largest extent is fit, centred over the origin, standing on y = 0 (> 0; default: as "
          "in the file)")
        .at_least(0)
        .in("world units");
    return s;
}

std::string accel_param(const Params& p) {
    const std::string accel = p.get_string("accel", "kd-sah");
    const std::vector<std::string> known = accelerator_methods();
    if (std::find(known.begin(), known.end(), accel) == known.end()) {
        std::string list;
        for (const auto& m : known) list += (list.empty() ? "" : ", ") + m;
        fail_param(p, "accel", "must be one of " + list + ", not '" + accel + "'");
    }
    return accel;
}
}  // namespace

void register_mesh(ShapeRegistry& registry) {
    registry.add(
        "mesh",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const std::string file = p.get_string("filename");
            const std::string accel = accel_param(p);
            const bool smooth = p.get_bool("smooth_normals", false);
            const float fit = p.has("fit") ? positive_float(p, "fit", 1.0f) : 0.0f;  // 0: as in the file
            MeshLoadInfo info;
            TriangleMesh loaded = load_mesh(file, &info);
            for (const auto& warning : info.warnings) p.warn(warning);
            if (smooth) loaded = with_smooth_normals(std::move(loaded));
            auto mesh = std::make_shared<TriangleMesh>(std::move(loaded));
            if (mesh->triangle_count() == 0) throw Error(p.context() + ": '" + file + "' has no triangles");
            return build(p, [&]() -> std::shared_ptr<Shape> {
                const AABB box = mesh->bounds();
                auto shape = std::make_shared<MeshShape>(std::move(mesh), accel);
                if (fit == 0.0f) return shape;
                return std::make_shared<Instance>(std::move(shape), fit_on_floor(box, fit));
            });
        },
        mesh_spec());
}

}  // namespace rtlab::scene_detail
