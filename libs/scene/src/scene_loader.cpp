// The JSON scene loader, in three stages: the document parsed with the position of every value
// (scene_json), each value checked against the declaration of its key (object_builder, json_values), the
// objects made by the registries (textures, materials, lights, shapes, the tone operator). It reads the whole
// file before it gives up: every problem becomes one line of the error it throws, so that a user fixes a
// scene in one pass. Nothing here knows any particular type: what a type takes is what it declares.
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include "json_values.hpp"
#include "load_context.hpp"
#include "object_builder.hpp"
#include "settings_reader.hpp"
#include "shape_reader.hpp"
#include "texture_reader.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace rtlab {

namespace fs = std::filesystem;

namespace {

using namespace scene_detail;

bool ends_with_ci(std::string_view s, std::string_view suffix) {
    if (s.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), s.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

template <class F>
void for_list(LoadContext& ctx, const Json& doc, const char* key, F&& each) {
    if (!doc.contains(key)) return;
    const Json& list = doc[key];
    const std::string p = pointer_append("", key);
    if (!list.is_array()) {
        ctx.error(p, "expected a list [ ... ], not " + describe(list));
        return;
    }
    for (std::size_t i = 0; i < list.size(); ++i) each(list[i], pointer_append(p, i));
}

// A name for an element of /textures, /materials or /lights; nullopt (reported) when missing, not a string,
// empty or taken.
template <class T>
std::optional<std::string> new_name(LoadContext& ctx, const Json& obj, const std::string& p,
                                    const std::map<std::string, Named<T>>& taken, Kind kind, bool required) {
    if (!obj.contains("name")) {
        if (required)
            ctx.error(p, std::string("missing key 'name': a ") + kind_name(kind) + " is referred to by its name");
        return std::nullopt;
    }
    auto name = read_string(ctx.diag, obj["name"], pointer_append(p, "name"));
    if (!name) return std::nullopt;
    if (name->empty()) {
        ctx.error(pointer_append(p, "name"), "a name must not be empty");
        return std::nullopt;
    }
    if (auto it = taken.find(*name); it != taken.end()) {
        ctx.error(pointer_append(p, "name"), std::string("duplicate ") + kind_name(kind) + " name '" + *name +
                                                 "' (first defined at " + it->second.pointer + ")");
        return std::nullopt;
    }
    return name;
}

void read_plugins(LoadContext& ctx, const Json& doc) {
    for_list(ctx, doc, "plugins", [&](const Json& v, const std::string& p) {
        auto name = read_string(ctx.diag, v, p);
        if (!name) return;
        if (name->empty() || name->find('/') != std::string::npos || name->find('\\') != std::string::npos ||
            ends_with_ci(*name, ".so") || name->front() == '.') {
            ctx.error(p, "'" + *name +
                             "' is not a plugin name: a scene names plugins by name only (\"myshader\"), never by a "
                             "path or a file name; they are found on the plugin search path (--plugin-dir)");
            return;
        }
        ctx.out.plugins.push_back(*name);
        if (!ctx.options.plugin_loader) {
            ctx.error(p, "the scene needs plugin '" + *name + "', but this program loads no plugins");
            return;
        }
        try {
            ctx.options.plugin_loader(*name);
        } catch (const std::exception& e) {
            ctx.error(p, "plugin '" + *name + "': " + e.what());
        }
    });
}

void read_version(LoadContext& ctx, const Json& doc) {
    if (!doc.contains("version")) {
        ctx.error("", "missing key 'version' (this loader reads version " + std::to_string(kSceneFormatVersion) + ")");
    } else if (auto v = read_integer(ctx.diag, doc["version"], "/version", 0, 1000000);
               v && *v != kSceneFormatVersion) {
        ctx.error("/version", "version " + std::to_string(*v) + " is not supported (this loader reads version " +
                                  std::to_string(kSceneFormatVersion) + ")");
    }
}

void read_document(LoadContext& ctx, const Json& doc) {
    if (!expect_object(ctx.diag, doc, "", "a scene")) return;
    check_keys(ctx.diag, doc, "",
               {"version", "description", "camera", "render", "plugins", "textures", "materials", "lights", "shapes"});
    read_version(ctx, doc);
    if (doc.contains("description")) read_string(ctx.diag, doc["description"], "/description");
    read_plugins(ctx, doc);
    for_list(ctx, doc, "textures", [&](const Json& t, const std::string& p) {
        if (!expect_object(ctx.diag, t, p, "a texture")) return;
        auto name = new_name(ctx, t, p, ctx.textures, Kind::texture, true);
        auto texture = read_texture(ctx, t, p, true);
        if (name) ctx.textures[*name] = {std::move(texture), p};
    });
    for_list(ctx, doc, "materials", [&](const Json& m, const std::string& p) {
        if (!expect_object(ctx.diag, m, p, "a material")) return;
        auto name = new_name(ctx, m, p, ctx.materials, Kind::material, true);
        auto material = read_material(ctx, m, p, true);
        if (name) ctx.materials[*name] = {std::move(material), p};
    });
    for_list(ctx, doc, "lights", [&](const Json& l, const std::string& p) {
        if (!expect_object(ctx.diag, l, p, "a light")) return;
        if (auto name = new_name(ctx, l, p, ctx.lights, Kind::light, false)) ctx.lights[*name] = {nullptr, p};
        BuildOptions options;
        options.loader_keys.push_back("name");
        if (auto light = build_object(ctx, ctx.registries.lights, Kind::light, l, p, options))
            ctx.out.job.lights.push_back(std::move(light));
    });
    std::vector<SceneObject> objects;
    for_list(ctx, doc, "shapes", [&](const Json& s, const std::string& p) { read_shape(ctx, s, p, objects); });
    if (!doc.contains("shapes")) ctx.error("", "missing key 'shapes': a scene needs at least one shape");
    const auto camera = read_camera(ctx, doc);
    read_render(ctx, doc, camera);
    set_auto_levels(ctx);
    if (!ctx.diag.empty()) return;
    try {
        ctx.out.job.scene = std::make_shared<const Scene>(std::move(objects));
    } catch (const Error& e) {
        ctx.error("/shapes", e.what());
    }
}

SceneRegistries& builtin_registries() {
    static SceneRegistries registries = SceneRegistries::builtins();
    return registries;
}

}  // namespace

LoadedScene parse_scene(std::string_view text, const fs::path& file, const SceneLoadOptions& options) {
    SceneRegistries& registries = options.registries ? *options.registries : builtin_registries();
    LoadContext ctx(file, options, registries);
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
        ctx.diag.error_at(0, "the file is empty (expected a JSON object with \"version\": " +
                                 std::to_string(kSceneFormatVersion) + ")");
        throw Error(ctx.diag.message());
    }
    std::optional<Json> doc = parse_json(text, ctx.diag);
    if (doc) read_document(ctx, *doc);
    if (!ctx.diag.empty()) throw Error(ctx.diag.message());
    return std::move(ctx.out);
}

LoadedScene load_scene(const fs::path& file, const SceneLoadOptions& options) {
    std::error_code ec;
    if (fs::is_directory(file, ec)) throw Error(file_error_message(file, "is a directory, not a scene file"));
    // 256 MiB: far beyond any scene, small enough that a wrong file (a mesh, an image) fails at once.
    const std::vector<unsigned char> bytes = read_binary_file(file, std::size_t{1} << 28);
    const std::string text(bytes.begin(), bytes.end());
    return parse_scene(text, file, options);
}

}  // namespace rtlab
