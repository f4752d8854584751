#include "texture_reader.hpp"

#include "json_values.hpp"
#include "object_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtlab::scene_detail {

namespace {

// The declared keys that name the texture's files.
std::vector<const ParamSpec*> file_params(const TypeSpec& spec) {
    std::vector<const ParamSpec*> out;
    for (const ParamSpec& p : spec.params())
        if (p.file_part) out.push_back(&p);
    return out;
}

// What is missing of the files the texture names, or nullopt when everything is found.
std::optional<std::string> missing_files(LoadContext& ctx, const Json& v, const std::vector<const ParamSpec*>& files) {
    for (const ParamSpec* f : files) {
        if (!v.contains(f->name) || !v[f->name].is_string()) continue;
        const std::string name = v[f->name].get<std::string>();
        if (f->kind == ParamKind::file && !ctx.has_file(name))
            return "file '" + name + "' not found (looked in " + ctx.where() + ")";
        if (f->kind == ParamKind::folder && !ctx.locate_folder(name))
            return "folder '" + name + "' not found (looked in " + ctx.where() + ")";
    }
    return std::nullopt;
}

// "fallback": a texture baked in place of the files of a texture that reads files, when they are not found.
// Built (and so checked) even when the files are there: a scene that works here must work elsewhere.
bool read_fallback(LoadContext& ctx, const Json& v, const std::string& p, BuildOptions& options) {
    const std::string fp = pointer_append(p, "fallback"), sp = pointer_append(p, "fallback_size");
    options.loader_keys.insert(options.loader_keys.end(), {"fallback", "fallback_size"});
    // The factory's errors about what the loader made of these keys belong at the keys.
    options.written_as = {{"bake", "fallback"}, {"bake_size", "fallback_size"}};
    if (!v.contains("fallback")) {
        ctx.error(sp, "'fallback_size' is only used with 'fallback'");
        return false;
    }
    const std::string type = v.contains("type") && v["type"].is_string() ? v["type"].get<std::string>() : "";
    const TypeSpec* spec = ctx.registries.textures.contains(type) ? &ctx.registries.textures.spec(type) : nullptr;
    const auto files = spec ? file_params(*spec) : std::vector<const ParamSpec*>{};
    if (!spec || files.empty() || !spec->find("bake")) {
        ctx.error(fp,
                  "'fallback' stands in for files that are not found: it is for textures that read files "
                  "(image, cubemap), not '" +
                      type + "'");
        return false;
    }
    std::shared_ptr<Texture> fallback;
    const Json& f = v["fallback"];
    if (f.is_string()) {
        auto it = ctx.textures.find(f.get<std::string>());
        if (it == ctx.textures.end()) {
            ctx.error(fp, "no texture named '" + f.get<std::string>() +
                              "' defined earlier in /textures (defined: " + join(names_of(ctx.textures)) + ")");
            return false;
        }
        fallback = it->second.object;
    } else if (f.is_object()) {
        std::vector<const Texture*>* outer = ctx.collecting;
        ctx.collecting = nullptr;  // baked: its own lookups never see the shapes
        fallback = read_texture(ctx, f, fp, false);
        ctx.collecting = outer;
    } else {
        ctx.error(fp, "expected a texture name or an inline texture, not " + describe(f));
        return false;
    }
    if (!fallback) return false;
    Params size;
    if (v.contains("fallback_size")) {
        const ParamSpec* bake_size = spec->find("bake_size");
        if (!bake_size) {
            ctx.error(sp, "texture type '" + type + "' takes no 'fallback_size'");
            return false;
        }
        if (!convert_param(ctx, *bake_size, v["fallback_size"], sp, size)) return false;
    }
    const std::optional<std::string> missing = missing_files(ctx, v, files);
    if (!missing) return true;
    options.extra.set_object<Texture>("bake", fallback);
    if (size.has("bake_size")) options.extra.set("bake_size", *size.get_value("bake_size"));
    for (const ParamSpec* file : files) options.left_out.push_back(file->name);
    ctx.warn(p, *missing + "; using its fallback");
    return true;
}

}  // namespace

std::shared_ptr<Texture> read_texture(LoadContext& ctx, const Json& v, const std::string& p, bool named) {
    if (!expect_object(ctx.diag, v, p, "a texture")) return nullptr;
    BuildOptions options;
    if (named) options.loader_keys.push_back("name");
    bool auto_lod = false;
    // "auto" for any texture type that declares a level of detail; others are told "lod" is not theirs.
    const std::string type = v.contains("type") && v["type"].is_string() ? v["type"].get<std::string>() : "";
    const bool has_levels = ctx.registries.textures.contains(type) && ctx.registries.textures.spec(type).find("lod");
    if (has_levels && v.contains("lod") && v["lod"].is_string()) {
        if (v["lod"] != "auto") {
            ctx.error(pointer_append(p, "lod"),
                      "expected a level of detail (a number >= 0) or \"auto\", not " + v["lod"].dump());
            return nullptr;
        }
        auto_lod = true;
        options.extra.set("lod", 0.0);  // the texture builds its levels now; the level is set once the camera is read
        options.loader_keys.push_back("lod");
    }
    // Textures the texture itself uses (a noise whose colours are images): a shape using it uses them too.
    std::vector<const Texture*> uses;
    std::vector<const Texture*>* outer = ctx.collecting;
    ctx.collecting = &uses;
    std::shared_ptr<Texture> texture;
    if (!(v.contains("fallback") || v.contains("fallback_size")) || read_fallback(ctx, v, p, options))
        texture = build_object(ctx, ctx.registries.textures, Kind::texture, v, p, options);
    ctx.collecting = outer;
    if (!texture) return nullptr;
    ctx.texture_uses[texture.get()] = std::move(uses);
    if (auto_lod) {
        auto* levels = dynamic_cast<LevelOfDetail*>(texture.get());
        if (!levels)
            ctx.error(pointer_append(p, "lod"),
                      "this texture type has no levels of detail; \"auto\" is for textures with levels (image, "
                      "cubemap)");
        else
            ctx.auto_levels[texture.get()] = AutoLevel{levels, {}, false};
    }
    return texture;
}

void set_auto_levels(LoadContext& ctx) {
    if (!ctx.camera) return;
    const float samples = filtering_samples(ctx.out.job.settings);
    for (auto& [texture, a] : ctx.auto_levels) {
        float lod = std::numeric_limits<float>::infinity();
        for (const UvFootprint& f : a.users)
            lod = std::min(lod, surface_texture_lod(*ctx.camera, f, a.levels->texels_u(), samples));
        if (a.environment) lod = std::min(lod, environment_texture_lod(*ctx.camera, a.levels->texels_u(), samples));
        a.levels->set_lod(std::isfinite(lod) ? lod : 0.0f);
    }
}

}  // namespace rtlab::scene_detail
