#include "shape_reader.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/core/spelling.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/transform.hpp>

#include "json_values.hpp"
#include "object_builder.hpp"

#include <algorithm>

namespace rtlab::scene_detail {

namespace {

std::optional<Mat4> read_matrix(LoadContext& ctx, const Json& v, const std::string& p) {
    std::vector<double> values;
    auto numbers = [](const Json& row, std::size_t n) {
        return row.is_array() && row.size() == n &&
               std::all_of(row.begin(), row.end(), [](const Json& x) { return x.is_number(); });
    };
    if (v.is_array() && v.size() == 4 &&
        std::all_of(v.begin(), v.end(), [&](const Json& r) { return numbers(r, 4); })) {
        for (const Json& row : v)
            for (const Json& x : row) values.push_back(x.get<double>());
    } else if (numbers(v, 16)) {
        for (const Json& x : v) values.push_back(x.get<double>());
    } else {
        ctx.error(p, "expected a 4x4 matrix: 4 rows of 4 numbers, or 16 numbers row by row, not " + describe(v));
        return std::nullopt;
    }
    if (values[12] != 0.0 || values[13] != 0.0 || values[14] != 0.0 || values[15] != 1.0) {
        ctx.error(p, "the last row must be [0, 0, 0, 1] (an affine transform)");
        return std::nullopt;
    }
    Mat4 m(1.0f);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            m[col][row] = static_cast<float>(values[static_cast<std::size_t>(row * 4 + col)]);
    return m;
}

std::optional<Mat4> read_transform_object(LoadContext& ctx, const Json& v, const std::string& p) {
    if (!expect_object(ctx.diag, v, p, "a transform {\"translate\", \"rotate\", \"scale\"} or {\"matrix\"}"))
        return std::nullopt;
    check_keys(ctx.diag, v, p, {"translate", "rotate", "scale", "matrix"});
    if (v.contains("matrix")) {
        if (v.contains("translate") || v.contains("rotate") || v.contains("scale")) {
            ctx.error(pointer_append(p, "matrix"), "give 'matrix' alone, or translate / rotate / scale without it");
            return std::nullopt;
        }
        return read_matrix(ctx, v["matrix"], pointer_append(p, "matrix"));
    }
    Vec3 translate(0.0f), rotate(0.0f), scale(1.0f);
    bool ok = true;
    for (const char* key : {"translate", "rotate"}) {
        if (!v.contains(key)) continue;
        if (auto x = read_vec3(ctx.diag, v[key], pointer_append(p, key)))
            (key[0] == 't' ? translate : rotate) = *x;
        else
            ok = false;
    }
    if (v.contains("scale")) {
        const std::string sp = pointer_append(p, "scale");
        std::optional<Vec3> k =
            v["scale"].is_number() ? Vec3(v["scale"].get<float>()) : read_vec3(ctx.diag, v["scale"], sp);
        if (k && (!is_finite(*k) || k->x == 0.0f || k->y == 0.0f || k->z == 0.0f)) {
            ctx.error(sp, "a scale must be finite and non-zero, not " + v["scale"].dump());
            k.reset();
        }
        if (k)
            scale = *k;
        else
            ok = false;
    }
    if (!ok) return std::nullopt;
    // A part not given is the identity, which multiplies exactly: the same matrix as leaving it out.
    return scene_transform(translate, rotate, scale);
}

// The shape's material: a name from /materials or an inline material.
std::optional<std::shared_ptr<const Material>> shape_material(LoadContext& ctx, const Json& m, const std::string& p) {
    if (m.is_string()) {
        const std::string name = m.get<std::string>();
        auto it = ctx.materials.find(name);
        if (it == ctx.materials.end()) {
            ctx.error(p, "no material named '" + name + "'" + did_you_mean(name, names_of(ctx.materials)) +
                             " (defined: " + join(names_of(ctx.materials)) + ")");
            return std::nullopt;
        }
        if (!it->second.object) return std::nullopt;
        return it->second.object;
    }
    if (m.is_object()) {
        auto material = read_material(ctx, m, p, false);
        if (!material) return std::nullopt;
        return material;
    }
    ctx.error(p, "expected a material name or an inline material object, not " + describe(m));
    return std::nullopt;
}

// Where the shape is seen, for the levels of the "auto" textures its material uses.
void note_footprint(LoadContext& ctx, const Shape& shape, const Material* material, const std::string& type,
                    const std::string& p) {
    auto it = ctx.material_uses.find(material);
    if (it == ctx.material_uses.end()) return;
    const std::optional<UvFootprint> where = shape.uv_footprint();
    for (const Texture* t : it->second) {
        auto a = ctx.auto_levels.find(t);
        if (a == ctx.auto_levels.end()) continue;
        if (!where) {
            ctx.error(pointer_append(p, "material"),
                      "uses a texture with \"lod\": \"auto\", which is worked out for shapes with a uv footprint "
                      "(spheres, disks), not a '" +
                          type + "'; give that texture a number as its lod");
            return;
        }
        a->second.users.push_back(*where);
    }
}

}  // namespace

std::optional<Mat4> read_transform(LoadContext& ctx, const Json& v, const std::string& p) {
    if (!v.is_array()) return read_transform_object(ctx, v, p);
    Mat4 m(1.0f);
    bool ok = true;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (auto step = read_transform_object(ctx, v[i], pointer_append(p, i)))
            m = *step * m;
        else
            ok = false;
    }
    if (!ok) return std::nullopt;
    return m;
}

std::shared_ptr<const Material> read_material(LoadContext& ctx, const Json& m, const std::string& p, bool named) {
    std::vector<const Texture*> uses;
    ctx.collecting = &uses;
    BuildOptions options;
    if (named) options.loader_keys.push_back("name");
    std::shared_ptr<const Material> material =
        build_object(ctx, ctx.registries.materials, Kind::material, m, p, options);
    ctx.collecting = nullptr;
    if (material) ctx.material_uses[material.get()] = std::move(uses);
    return material;
}

void read_shape(LoadContext& ctx, const Json& s, const std::string& p, std::vector<SceneObject>& objects) {
    if (!expect_object(ctx.diag, s, p, "a shape")) return;
    std::optional<std::string> name;
    if (s.contains("name")) {
        name = read_string(ctx.diag, s["name"], pointer_append(p, "name"));
        if (name && name->empty()) {
            ctx.error(pointer_append(p, "name"), "a name must not be empty");
            name.reset();
        } else if (name && ctx.shapes.contains(*name)) {
            ctx.error(pointer_append(p, "name"),
                      "duplicate shape name '" + *name + "' (first defined at " + ctx.shapes[*name].pointer + ")");
            name.reset();
        }
    }
    SurfaceFlags flags;
    bool visible = true, ok = true;
    if (s.contains("casts_shadows"))
        if (auto b = read_boolean(ctx.diag, s["casts_shadows"], pointer_append(p, "casts_shadows")))
            flags.casts_shadows = *b;
    if (s.contains("reversed"))
        if (auto b = read_boolean(ctx.diag, s["reversed"], pointer_append(p, "reversed"))) flags.reversed = *b;
    if (s.contains("visible"))
        if (auto b = read_boolean(ctx.diag, s["visible"], pointer_append(p, "visible"))) visible = *b;
    std::optional<Mat4> transform;
    if (s.contains("transform")) {
        transform = read_transform(ctx, s["transform"], pointer_append(p, "transform"));
        ok = ok && transform;
    }
    std::shared_ptr<const Material> material;
    if (s.contains("material")) {
        auto m = shape_material(ctx, s["material"], pointer_append(p, "material"));
        ok = ok && m;
        if (m) material = *m;
    } else if (visible) {
        ctx.error(p, "missing key 'material' (only a shape with \"visible\": false, kept for instances, has none)");
        ok = false;
    }
    BuildOptions options;
    options.loader_keys = {"name", "material", "transform", "casts_shadows", "reversed", "visible"};
    const bool is_instance = s.contains("type") && s["type"] == "instance";
    if (is_instance && transform) {
        Params::List m;
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col) m.push_back((*transform)[col][row]);
        options.extra.set("matrix", std::move(m));
    }
    std::shared_ptr<const Shape> shape = build_object(ctx, ctx.registries.shapes, Kind::shape, s, p, options);
    if (shape && transform && !is_instance) {
        try {
            shape = std::make_shared<const Instance>(shape, *transform);
        } catch (const Error& e) {
            ctx.error(pointer_append(p, "transform"), e.what());
            shape = nullptr;
        }
    }
    if (name) ctx.shapes[*name] = {shape, p};
    if (!shape || !ok || !visible) return;
    note_footprint(ctx, *shape, material.get(), s["type"].get<std::string>(), p);
    objects.push_back({shape, material, flags, name ? *name : p});
}

}  // namespace rtlab::scene_detail
