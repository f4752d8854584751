// The built-in shapes by name. Points and vectors are lists of 3 finite numbers; lengths are finite and > 0.
#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/param_checks.hpp>
#include <rtlab/geometry/box.hpp>
#include <rtlab/geometry/cylinder.hpp>
#include <rtlab/geometry/disk.hpp>
#include <rtlab/geometry/fit_on_floor.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/mesh_io.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/smooth_normals.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/geometry/triangle_shape.hpp>
#include <rtlab/scene/shape_registry.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace rtlab {

namespace {

Vec3 vec3_param(const Params& p, std::string_view name, const Vec3& fallback) {
    if (!p.has(name)) return fallback;
    const Params::List l = p.get_list(name);
    if (l.size() != 3) fail_param(p, name, "must be a list of 3 numbers, not " + std::to_string(l.size()));
    const Vec3 v(static_cast<float>(l[0]), static_cast<float>(l[1]), static_cast<float>(l[2]));
    if (!is_finite(v)) fail_param(p, name, "must be finite (a float)");
    return v;
}

Vec3 required_vec3(const Params& p, std::string_view name) {
    if (!p.has(name)) fail_param(p, name, "is missing");
    return vec3_param(p, name, Vec3(0.0f));
}

// The geometry constructors say what is wrong ("disk: radius must be positive"); the context says which object.
template <class F>
std::shared_ptr<Shape> build(const Params& p, F&& f) {
    try {
        return f();
    } catch (const Error& e) {
        throw Error(p.context() + ": " + e.what());
    }
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

void register_builtins(ShapeRegistry& r) {
    r.add(
        "sphere",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 c = vec3_param(p, "center", Vec3(0.0f));
            const float radius = positive_float(p, "radius", 1.0f);
            return build(p, [&] { return std::make_shared<Sphere>(c, radius); });
        },
        "sphere. center [x, y, z] (default [0, 0, 0]); radius > 0 (default 1). uv: longitude, latitude (v = 1 at +y)");
    r.add(
        "disk",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 c = vec3_param(p, "center", Vec3(0.0f));
            const Vec3 n = vec3_param(p, "normal", Vec3(0.0f, 1.0f, 0.0f));
            const float radius = positive_float(p, "radius", 1.0f);
            const float inner = positive_float(p, "inner_radius", 0.0f, true);
            return build(p, [&] { return std::make_shared<Disk>(c, n, radius, inner); });
        },
        "flat disk or annulus. center (default [0, 0, 0]); normal, its outside (default [0, 1, 0]); radius > 0 "
        "(default 1); inner_radius in [0, radius) (default 0: no hole). uv: u from the inner to the outer edge, v "
        "the angle / 2 pi");
    r.add(
        "quad",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 corner = required_vec3(p, "corner"), u = required_vec3(p, "edge_u"),
                       v = required_vec3(p, "edge_v");
            return build(p, [&] { return std::make_shared<Quad>(corner, u, v); });
        },
        "parallelogram corner + a edge_u + b edge_v, a, b in [0, 1]. corner, edge_u, edge_v (required); outside "
        "is the side of edge_u x edge_v; uv = (a, b)");
    r.add(
        "box",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 lo = required_vec3(p, "min"), hi = required_vec3(p, "max");
            if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) fail_param(p, "max", "must exceed 'min' on every axis");
            return build(p, [&] { return std::make_shared<Box>(AABB{lo, hi}); });
        },
        "axis-aligned solid box. min, max: opposite corners (required)");
    r.add(
        "cylinder",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const Vec3 base = vec3_param(p, "base", Vec3(0.0f)), top = vec3_param(p, "top", Vec3(0.0f, 1.0f, 0.0f));
            const float radius = positive_float(p, "radius", 1.0f);
            const bool caps = p.get_bool("caps", true);
            if (base == top) fail_param(p, "top", "must differ from 'base'");
            return build(p, [&] { return std::make_shared<Cylinder>(base, top, radius, caps); });
        },
        "finite cylinder. base (default [0, 0, 0]), top (default [0, 1, 0]); radius > 0 (default 1); caps: "
        "true | false, closed ends (default true)");
    r.add(
        "triangle",
        [](const Params& p) -> std::shared_ptr<Shape> {
            auto mesh = std::make_shared<TriangleMesh>();
            mesh->positions = {required_vec3(p, "p0"), required_vec3(p, "p1"), required_vec3(p, "p2")};
            mesh->triangles = {{0u, 1u, 2u}};
            if (mesh->is_degenerate(0)) throw Error(p.context() + ": the three corners are collinear or repeated");
            return std::make_shared<TriangleShape>(std::move(mesh), 0u);
        },
        "one triangle. p0, p1, p2 (required); outside is the side of (p1 - p0) x (p2 - p0)");
    r.add(
        "mesh",
        [](const Params& p) -> std::shared_ptr<Shape> {
            const std::string file = p.get_string("filename");
            const std::string accel = one_of(p, "accel", "kd-sah",
                                             {"kd-sah", "kd-sah-binned", "kd-sah-naive", "kd-median", "kd-midpoint",
                                              "kd-three-way", "bvh", "octree", "brute"});
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
        "triangle mesh from a PLY or OBJ file, with its own acceleration structure. filename (required; found "
        "beside the scene, then on the data path); accel: kd-sah | kd-sah-binned | kd-sah-naive | kd-median | "
        "kd-midpoint | kd-three-way | bvh | octree | brute (default kd-sah); smooth_normals: true | false, "
        "area-weighted vertex normals when the file has none (default false); fit > 0: scaled so that its largest "
        "extent is fit, centred over the origin, standing on y = 0 (default: as in the file)");
    r.add(
        "instance",
        [](const Params& p) -> std::shared_ptr<Shape> {
            auto shape = p.get_object<const Shape>("shape");
            if (!shape) fail_param(p, "shape", "is missing: name the shape to show again");
            const Mat4 m = matrix_param(p);
            return build(p, [&] { return std::make_shared<Instance>(std::move(shape), m); });
        },
        "another copy of a named shape (usually a mesh, whose tree it shares) with its own transform and "
        "material. shape: the name (required); matrix: 16 numbers row by row (a scene file gives 'transform')");
}

ShapeRegistry make_shape_registry() {
    ShapeRegistry registry("shape");
    register_builtins(registry);
    return registry;
}

}  // namespace rtlab
