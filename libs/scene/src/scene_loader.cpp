// The JSON scene loader. It reads the whole file before it gives up: every problem becomes one line of the
// error it throws, so a user fixes a scene in one pass rather than one error per run.
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/core/search_path.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/scene/scene_loader.hpp>
#include <rtlab/render/texture_level.hpp>
#include <rtlab/render/thin_lens_camera.hpp>
#include <rtlab/textures/mip_map.hpp>

#include "scene_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <system_error>

namespace rtlab {

namespace fs = std::filesystem;
using scene_detail::describe;
using scene_detail::Diagnostics;
using scene_detail::Json;
using scene_detail::pointer_append;

namespace {

// Keys whose string values are words or file names for the built-in types, never texture names.
const std::set<std::string, std::less<>> kTextureWords = {"pattern",   "wrap",     "wrap_v", "filter", "encoding",
                                                          "extension", "filename", "cross",  "folder", "px",
                                                          "nx",        "py",       "ny",     "pz",     "nz"};
const std::set<std::string, std::less<>> kMaterialWords = {"metal", "distribution"};
const std::set<std::string, std::less<>> kCubeFaces = {"px", "nx", "py", "ny", "pz", "nz", "cross"};
// The keys that name a texture's files: dropped when the files are missing and its fallback is baked instead.
const std::set<std::string, std::less<>> kFileKeys = {"filename", "folder", "extension", "cross", "px",
                                                      "nx",       "py",     "ny",        "pz",    "nz"};

std::string join(const std::vector<std::string>& words) {
    std::string out;
    for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
    return out.empty() ? "(none)" : out;
}

template <class Map>
std::vector<std::string> keys_of(const Map& m) {
    std::vector<std::string> out;
    for (const auto& [k, v] : m) out.push_back(k);
    return out;
}

bool ends_with_ci(std::string_view s, std::string_view suffix) {
    if (s.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), s.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

// The categories of named objects; each has its own names.
enum class Kind { texture, material, light, shape };

const char* kind_name(Kind k) {
    switch (k) {
        case Kind::texture:
            return "texture";
        case Kind::material:
            return "material";
        case Kind::light:
            return "light";
        default:
            return "shape";
    }
}

// A named object and where it was defined; null object when building it failed (its error is reported once,
// and references to it are not reported again).
template <class T>
struct Named {
    std::shared_ptr<T> object;
    std::string pointer;
};

class Loader {
public:
    Loader(const fs::path& file, const SceneLoadOptions& options, SceneRegistries& registries)
        : m_diag(file.string()),
          m_folder(file.has_parent_path() ? file.parent_path() : fs::path()),
          m_options(options),
          m_reg(registries) {
        m_search = options.use_environment ? SearchPath::from_environment(options.data_dirs, kDataPathVariable)
                                           : SearchPath(options.data_dirs);
        const SceneRegistries builtin = SceneRegistries::builtins();
        for (auto& n : builtin.textures.names()) m_builtin[Kind::texture].insert(n);
        for (auto& n : builtin.materials.names()) m_builtin[Kind::material].insert(n);
        for (auto& n : builtin.lights.names()) m_builtin[Kind::light].insert(n);
        for (auto& n : builtin.shapes.names()) m_builtin[Kind::shape].insert(n);
    }

    Diagnostics& diag() { return m_diag; }

    LoadedScene load(std::string_view text) {
        if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
            m_diag.error_at(0, "the file is empty (expected a JSON object with \"version\": " +
                                   std::to_string(kSceneFormatVersion) + ")");
            fail();
        }
        std::optional<Json> doc = scene_detail::parse_json(text, m_diag);
        if (!doc) fail();
        read_document(*doc);
        if (!m_diag.empty()) fail();
        return std::move(m_out);
    }

private:
    [[noreturn]] void fail() { throw Error(m_diag.message()); }

    // ---- checked reads of single values ----

    void error(const std::string& pointer, const std::string& message) { m_diag.error(pointer, message); }

    bool expect_object(const Json& v, const std::string& p, const std::string& what) {
        if (v.is_object()) return true;
        error(p, "expected " + what + " (a JSON object), not " + describe(v));
        return false;
    }

    void check_keys(const Json& obj, const std::string& p, std::initializer_list<std::string_view> allowed) {
        for (const auto& [key, value] : obj.items()) {
            if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
            std::string list;
            for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            error(pointer_append(p, key), "unknown key '" + key + "'; expected one of: " + list);
        }
    }

    std::optional<double> number(const Json& v, const std::string& p, double lo, double hi) {
        if (!v.is_number()) {
            error(p, "expected a number, not " + describe(v));
            return std::nullopt;
        }
        const double x = v.get<double>();
        if (!(x >= lo && x <= hi)) {
            error(p, "must be in [" + Json(lo).dump() + ", " + Json(hi).dump() + "], not " + v.dump());
            return std::nullopt;
        }
        return x;
    }

    std::optional<std::int64_t> integer(const Json& v, const std::string& p, std::int64_t lo, std::int64_t hi) {
        if (!v.is_number() || (v.is_number_float() && std::trunc(v.get<double>()) != v.get<double>())) {
            error(p, "expected an integer, not " + describe(v));
            return std::nullopt;
        }
        const double x = v.get<double>();
        if (!(x >= static_cast<double>(lo) && x <= static_cast<double>(hi))) {
            error(p, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + v.dump());
            return std::nullopt;
        }
        return v.is_number_unsigned() ? static_cast<std::int64_t>(v.get<std::uint64_t>()) : v.get<std::int64_t>();
    }

    std::optional<std::string> string(const Json& v, const std::string& p) {
        if (!v.is_string()) {
            error(p, "expected a string, not " + describe(v));
            return std::nullopt;
        }
        return v.get<std::string>();
    }

    std::optional<bool> boolean(const Json& v, const std::string& p) {
        if (!v.is_boolean()) {
            error(p, "expected true or false, not " + describe(v));
            return std::nullopt;
        }
        return v.get<bool>();
    }

    std::optional<Vec3> vec3(const Json& v, const std::string& p) {
        if (!v.is_array() || v.size() != 3 ||
            !std::all_of(v.begin(), v.end(), [](const Json& x) { return x.is_number(); })) {
            error(p, "expected a list of 3 numbers [x, y, z], not " + describe(v));
            return std::nullopt;
        }
        const Vec3 out(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
        if (!is_finite(out)) {
            error(p, "must be finite (representable as a float), not " + v.dump());
            return std::nullopt;
        }
        return out;
    }

    std::optional<RGB> colour(const Json& v, const std::string& p) {
        RGB c;
        if (v.is_number()) {
            c = RGB(v.get<float>());
        } else if (v.is_array() && v.size() == 3 &&
                   std::all_of(v.begin(), v.end(), [](const Json& x) { return x.is_number(); })) {
            c = RGB(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
        } else {
            error(p, "expected a colour (a number or a list of 3 numbers [r, g, b]), not " + describe(v));
            return std::nullopt;
        }
        if (!c.is_finite() || c.r < 0.0f || c.g < 0.0f || c.b < 0.0f) {
            error(p, "a colour must be finite and >= 0, not " + v.dump());
            return std::nullopt;
        }
        return c;
    }

    // ---- files ----

    std::optional<std::string> find_file(const std::string& name, const std::string& p) {
        if (name.empty()) {
            error(p, "expected a file name, not an empty string");
            return std::nullopt;
        }
        if (auto found = m_search.find(name, m_folder)) return found->string();
        std::error_code ec;
        const fs::path beside = m_folder / name;
        if (fs::is_directory(fs::path(name).is_absolute() ? fs::path(name) : beside, ec)) {
            error(p, "'" + name + "' is a directory, not a file");
            return std::nullopt;
        }
        error(p, "file '" + name + "' not found (looked in " + where() + ")");
        return std::nullopt;
    }

    std::optional<std::string> find_folder(const std::string& name, const std::string& p) {
        std::error_code ec;
        std::vector<fs::path> tries;
        if (fs::path(name).is_absolute()) {
            tries.push_back(name);
        } else {
            tries.push_back(m_folder / name);
            for (const auto& f : m_search.folders()) tries.push_back(f / name);
        }
        for (const auto& t : tries)
            if (fs::is_directory(t, ec)) return t.string();
        error(p, "folder '" + name + "' not found (looked in " + where() + ")");
        return std::nullopt;
    }

    std::string where() const {
        std::string out = "'" + (m_folder.empty() ? std::string(".") : m_folder.string()) + "' (the scene's folder)";
        for (const auto& f : m_search.folders()) out += ", '" + f.string() + "'";
        if (m_search.folders().empty()) out += "; add folders with --data-dir or " + std::string(kDataPathVariable);
        return out;
    }

    // ---- objects made by the registries ----

    // Turns one key of an object into a parameter. Returns false when the object cannot be built.
    bool convert(Kind kind, const std::string& type, const std::string& key, const Json& v, const std::string& p,
                 Params& params) {
        const bool builtin = m_builtin[kind].contains(type);
        switch (v.type()) {
            case Json::value_t::boolean:
                params.set(key, v.get<bool>());
                return true;
            case Json::value_t::number_integer:
            case Json::value_t::number_unsigned:
            case Json::value_t::number_float:
                params.set(key, v.get<double>());
                return true;
            case Json::value_t::array: {
                Params::List list;
                for (const Json& x : v) {
                    if (!x.is_number()) {
                        error(p, "expected a number or a list of numbers, not a list holding " + describe(x));
                        return false;
                    }
                    list.push_back(x.get<double>());
                }
                params.set(key, std::move(list));
                return true;
            }
            case Json::value_t::object: {
                if (kind != Kind::texture && kind != Kind::material) break;
                auto texture = make_texture(v, p, false);  // an inline texture
                if (!texture) return false;
                note_use(texture.get());
                params.set_object<Texture>(key, std::move(texture));
                return true;
            }
            case Json::value_t::string: {
                const std::string s = v.get<std::string>();
                // File names: found beside the scene or on the data path before the factory opens them.
                const bool is_cube_file = kind == Kind::texture && type == "cubemap" && kCubeFaces.contains(key);
                if (key == "filename" || is_cube_file) {
                    auto file = find_file(s, p);
                    if (!file) return false;
                    params.set(key, *file);
                    return true;
                }
                if (key == "folder" && kind == Kind::texture) {
                    auto folder = find_folder(s, p);
                    if (!folder) return false;
                    params.set(key, *folder);
                    return true;
                }
                if (kind == Kind::shape && key == "shape") return shape_reference(s, p, params, key);
                const bool word = (kind == Kind::texture && kTextureWords.contains(key)) ||
                                  (kind == Kind::material && kMaterialWords.contains(key));
                if ((kind == Kind::texture || kind == Kind::material) && !word) {
                    if (auto it = m_textures.find(s); it != m_textures.end()) {
                        if (!it->second.object) return false;  // its own error is already reported
                        note_use(it->second.object.get());
                        params.set_object<Texture>(key, it->second.object);
                        return true;
                    }
                    if (builtin) {
                        error(p, "no texture named '" + s +
                                     "'; expected a colour (a number or [r, g, b]) or the name of "
                                     "a texture defined earlier in /textures (defined: " +
                                     join(keys_of(m_textures)) + ")");
                        return false;
                    }
                }
                params.set(key, s);  // a word for the factory (a plugin's own string parameters too)
                return true;
            }
            default:
                break;
        }
        error(p, "expected a number, a list of numbers, a string or true/false, not " + describe(v));
        return false;
    }

    bool shape_reference(const std::string& name, const std::string& p, Params& params, const std::string& key) {
        auto it = m_shapes.find(name);
        if (it == m_shapes.end()) {
            error(p, "no shape named '" + name +
                         "' defined earlier in /shapes (named shapes: " + join(keys_of(m_shapes)) + ")");
            return false;
        }
        if (!it->second.object) return false;
        params.set_object<const Shape>(key, it->second.object);
        return true;
    }

    // Reports a factory's error at the key it names, so that it gets the key's line.
    void factory_error(Kind kind, const std::string& type, const Json& obj, const std::string& p,
                       const std::string& what) {
        const std::string unused = "unknown or unused parameter(s) ";
        if (const auto at = what.find(unused); at != std::string::npos) {
            std::string rest = what.substr(at + unused.size());
            std::size_t q = 0;
            while ((q = rest.find('\'')) != std::string::npos) {
                const auto end = rest.find('\'', q + 1);
                if (end == std::string::npos) break;
                const std::string key = rest.substr(q + 1, end - q - 1);
                error(pointer_append(p, key), "unknown key '" + key + "' for " + kind_name(kind) + " type '" + type +
                                                  "' (rtlab-render --list shows each type's keys)");
                rest = rest.substr(end + 1);
            }
            return;
        }
        const std::string param = "parameter '";
        if (const auto at = what.find(param); at != std::string::npos) {
            const auto end = what.find('\'', at + param.size());
            const std::string key = what.substr(at + param.size(), end - at - param.size());
            if (obj.contains(key)) {
                error(pointer_append(p, key), what);
                return;
            }
        }
        error(p, what);
    }

    // The object's "type", checked against the registry; nullopt (reported) when missing or unknown.
    template <class Base>
    std::optional<std::string> type_of(const Registry<Base>& registry, Kind kind, const Json& obj,
                                       const std::string& p) {
        if (!obj.contains("type")) {
            error(p, std::string("missing key 'type'; expected one of: ") + join(registry.names()));
            return std::nullopt;
        }
        auto type = string(obj["type"], pointer_append(p, "type"));
        if (!type) return std::nullopt;
        if (!registry.contains(*type)) {
            error(pointer_append(p, "type"), "unknown " + std::string(kind_name(kind)) + " type '" + *type +
                                                 "'; known: " + join(registry.names()));
            return std::nullopt;
        }
        return type;
    }

    template <class Base>
    std::shared_ptr<Base> create(const Registry<Base>& registry, Kind kind, const Json& obj, const std::string& p,
                                 const std::vector<std::string_view>& loader_keys, const Params& extra = {}) {
        const auto type = type_of(registry, kind, obj, p);
        if (!type) return nullptr;
        Params params = extra;
        bool ok = true;
        for (const auto& [key, value] : obj.items()) {
            if (key == "type" || std::find(loader_keys.begin(), loader_keys.end(), key) != loader_keys.end()) continue;
            ok = convert(kind, *type, key, value, pointer_append(p, key), params) && ok;
        }
        if (!ok) return nullptr;
        params.set_warning_sink([this, p](const std::string& message) { warn(p, message); });
        try {
            auto object = registry.create(*type, std::move(params));
            if (!object) error(p, std::string(kind_name(kind)) + " type '" + *type + "' made nothing");
            return object;
        } catch (const Error& e) {
            factory_error(kind, *type, obj, p, e.what());
        } catch (const std::exception& e) {
            error(p, std::string(kind_name(kind)) + " type '" + *type + "' failed: " + e.what());
        }
        return nullptr;
    }

    // A name for a named list's element; nullopt (reported) when missing, not a string, or taken.
    template <class T>
    std::optional<std::string> new_name(const Json& obj, const std::string& p,
                                        const std::map<std::string, Named<T>>& taken, Kind kind, bool required) {
        if (!obj.contains("name")) {
            if (required)
                error(p, std::string("missing key 'name': a ") + kind_name(kind) + " is referred to by its name");
            return std::nullopt;
        }
        auto name = string(obj["name"], pointer_append(p, "name"));
        if (!name) return std::nullopt;
        if (name->empty()) {
            error(pointer_append(p, "name"), "a name must not be empty");
            return std::nullopt;
        }
        if (auto it = taken.find(*name); it != taken.end()) {
            error(pointer_append(p, "name"), std::string("duplicate ") + kind_name(kind) + " name '" + *name +
                                                 "' (first defined at " + it->second.pointer + ")");
            return std::nullopt;
        }
        return name;
    }

    std::shared_ptr<Texture> make_texture(const Json& v, const std::string& p, bool named) {
        if (!expect_object(v, p, "a texture")) return nullptr;
        std::vector<std::string_view> loader_keys;
        if (named) loader_keys.push_back("name");
        Params extra;
        bool auto_lod = false;
        if (v.contains("lod") && v["lod"].is_string()) {
            if (v["lod"] != "auto") {
                error(pointer_append(p, "lod"),
                      "expected a level of detail (a number >= 0) or \"auto\", not " + v["lod"].dump());
                return nullptr;
            }
            auto_lod = true;
            extra.set("lod", 0.0);  // the texture builds its levels now; the level is set once the camera is read
            loader_keys.push_back("lod");
        }
        // Textures the texture itself uses (a noise whose colours are images): a shape using it uses them too.
        std::vector<const Texture*> uses;
        std::vector<const Texture*>* outer = m_collect;
        m_collect = &uses;
        std::shared_ptr<Texture> texture;
        if (v.contains("fallback") || v.contains("fallback_size")) {
            loader_keys.push_back("fallback");
            loader_keys.push_back("fallback_size");
            if (read_fallback(v, p, extra, loader_keys))
                texture = create(m_reg.textures, Kind::texture, v, p, loader_keys, extra);
        } else {
            texture = create(m_reg.textures, Kind::texture, v, p, loader_keys, extra);
        }
        m_collect = outer;
        if (!texture) return nullptr;
        m_texture_uses[texture.get()] = std::move(uses);
        if (auto_lod) {
            auto* levels = dynamic_cast<LevelOfDetail*>(texture.get());
            if (!levels)
                error(pointer_append(p, "lod"),
                      "this texture type has no levels of detail; \"auto\" is for image "
                      "and cubemap textures");
            else
                m_auto_lod[texture.get()] = AutoLevel{levels, {}, false};
        }
        return texture;
    }

    // "fallback": a texture baked in place of the files of an image or cubemap texture when they are not found.
    // Adds "bake" (and "bake_size") to `extra` and the file keys to `loader_keys` (so they are not passed on)
    // when the files are missing. False when the fallback itself is wrong (reported).
    bool read_fallback(const Json& v, const std::string& p, Params& extra, std::vector<std::string_view>& loader_keys) {
        const std::string fp = pointer_append(p, "fallback"), sp = pointer_append(p, "fallback_size");
        if (!v.contains("fallback")) {
            error(sp, "'fallback_size' is only used with 'fallback'");
            return false;
        }
        const std::string type = v.contains("type") && v["type"].is_string() ? v["type"].get<std::string>() : "";
        if (type != "image" && type != "cubemap") {
            error(fp, "'fallback' stands in for files that are not found: it is for image and cubemap textures, not '" +
                          type + "'");
            return false;
        }
        // Built (and so checked) even when the files are there: a scene that works here must work elsewhere.
        std::shared_ptr<Texture> fallback;
        const Json& f = v["fallback"];
        if (f.is_string()) {
            auto it = m_textures.find(f.get<std::string>());
            if (it == m_textures.end()) {
                error(fp, "no texture named '" + f.get<std::string>() +
                              "' defined earlier in /textures (defined: " + join(keys_of(m_textures)) + ")");
                return false;
            }
            fallback = it->second.object;
        } else if (f.is_object()) {
            std::vector<const Texture*>* outer = m_collect;
            m_collect = nullptr;  // baked: its own lookups never see the shapes
            fallback = make_texture(f, fp, false);
            m_collect = outer;
        } else {
            error(fp, "expected a texture name or an inline texture, not " + describe(f));
            return false;
        }
        if (!fallback) return false;
        Params size;
        if (v.contains("fallback_size")) {
            const Json& z = v["fallback_size"];
            if (type == "image") {
                if (!z.is_array() || z.size() != 2) {
                    error(sp, "expected [width, height] of the baked image, not " + describe(z));
                    return false;
                }
                auto w = integer(z[0], pointer_append(sp, 0), 1, 16384),
                     h = integer(z[1], pointer_append(sp, 1), 1, 16384);
                if (!w || !h) return false;
                size.set("bake_size", Params::List{static_cast<double>(*w), static_cast<double>(*h)});
            } else {
                auto n = integer(z, sp, 1, 8192);
                if (!n) return false;
                size.set("bake_size", static_cast<double>(*n));
            }
        }
        const std::optional<std::string> missing = missing_files(v, type);
        if (!missing) return true;
        extra.set_object<Texture>("bake", fallback);
        if (size.has("bake_size")) extra.set("bake_size", *size.get_value("bake_size"));
        for (const auto& key : kFileKeys) loader_keys.push_back(key);
        warn(p, *missing + "; using its fallback");
        return true;
    }

    // A non-fatal problem at JSON pointer p, named by file and position like the errors.
    void warn(const std::string& p, const std::string& message) {
        const std::string pos = m_diag.position(p);
        m_out.warnings.push_back(m_diag.file() + (pos.empty() ? "" : ":" + pos) + ": " + p + ": " + message);
    }

    // What is missing of an image or cubemap texture's files, or nullopt when everything is found.
    std::optional<std::string> missing_files(const Json& v, const std::string& type) {
        auto file = [&](const std::string& name) -> std::optional<std::string> {
            if (m_search.find(name, m_folder)) return std::nullopt;
            return "file '" + name + "' not found (looked in " + where() + ")";
        };
        auto text = [&](const char* key) {
            return v.contains(key) && v[key].is_string() ? v[key].get<std::string>() : "";
        };
        if (type == "image") return file(text("filename"));
        if (v.contains("cross")) return file(text("cross"));
        if (v.contains("folder")) {
            const std::string folder = text("folder");
            const std::string ext = v.contains("extension") ? text("extension") : "jpg";
            for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"})
                if (auto m = file((fs::path(folder) / (std::string(face) + "." + ext)).string())) return m;
            return std::nullopt;
        }
        for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"})
            if (v.contains(face))
                if (auto m = file(text(face))) return m;
        return std::nullopt;
    }

    void note_use(const Texture* texture) {
        if (!m_collect || !texture) return;
        m_collect->push_back(texture);
        if (auto it = m_texture_uses.find(texture); it != m_texture_uses.end())
            m_collect->insert(m_collect->end(), it->second.begin(), it->second.end());
    }

    // A material with the textures it uses (their own textures included).
    std::shared_ptr<const Material> make_material(const Json& m, const std::string& p,
                                                  const std::vector<std::string_view>& loader_keys) {
        std::vector<const Texture*> uses;
        m_collect = &uses;
        auto material = create(m_reg.materials, Kind::material, m, p, loader_keys);
        m_collect = nullptr;
        if (material) m_material_uses[material.get()] = std::move(uses);
        return material;
    }

    // Where a sphere or disk lies, for the levels of its "auto" textures; nullopt for other shapes.
    std::optional<UvFootprint> footprint(const Json& s, const std::string& p, const std::optional<Mat4>& transform) {
        const std::string type = s["type"].get<std::string>();
        if (type != "sphere" && type != "disk") return std::nullopt;
        const Mat4 m = transform.value_or(Mat4(1.0f));
        Vec3 centre(0.0f);
        if (s.contains("center"))
            if (auto c = vec3(s["center"], pointer_append(p, "center"))) centre = *c;
        auto value = [&](const char* key, float fallback) {
            return s.contains(key) && s[key].is_number() ? s[key].get<float>() : fallback;
        };
        if (type == "sphere") return sphere_footprint(m, centre, value("radius", 1.0f));
        return disk_footprint(m, centre, value("radius", 1.0f), value("inner_radius", 0.0f));
    }

    // Sets the level of every "auto" texture: the finest any shape using it (or the sky) asks for.
    void set_auto_levels() {
        if (!m_camera) return;
        const float samples = filtering_samples(m_out.job.settings);
        for (auto& [texture, a] : m_auto_lod) {
            float lod = std::numeric_limits<float>::infinity();
            for (const UvFootprint& f : a.users)
                lod = std::min(lod, surface_texture_lod(*m_camera, f, a.levels->texels_u(), samples));
            if (a.environment) lod = std::min(lod, environment_texture_lod(*m_camera, a.levels->texels_u(), samples));
            a.levels->set_lod(std::isfinite(lod) ? lod : 0.0f);
        }
    }

    // ---- the document ----

    template <class F>
    void for_list(const Json& doc, const char* key, F&& each) {
        if (!doc.contains(key)) return;
        const Json& list = doc[key];
        const std::string p = pointer_append("", key);
        if (!list.is_array()) {
            error(p, "expected a list [ ... ], not " + describe(list));
            return;
        }
        for (std::size_t i = 0; i < list.size(); ++i) each(list[i], pointer_append(p, i));
    }

    void read_document(const Json& doc) {
        if (!expect_object(doc, "", "a scene")) return;
        check_keys(
            doc, "",
            {"version", "description", "camera", "render", "plugins", "textures", "materials", "lights", "shapes"});
        if (!doc.contains("version")) {
            error("", "missing key 'version' (this loader reads version " + std::to_string(kSceneFormatVersion) + ")");
        } else if (auto v = integer(doc["version"], "/version", 0, 1000000); v && *v != kSceneFormatVersion) {
            error("/version", "version " + std::to_string(*v) + " is not supported (this loader reads version " +
                                  std::to_string(kSceneFormatVersion) + ")");
        }
        if (doc.contains("description")) string(doc["description"], "/description");
        read_plugins(doc);
        for_list(doc, "textures", [&](const Json& t, const std::string& p) {
            if (!expect_object(t, p, "a texture")) return;
            auto name = new_name(t, p, m_textures, Kind::texture, true);
            auto texture = make_texture(t, p, true);
            if (name) m_textures[*name] = {std::move(texture), p};
        });
        for_list(doc, "materials", [&](const Json& m, const std::string& p) {
            if (!expect_object(m, p, "a material")) return;
            auto name = new_name(m, p, m_materials, Kind::material, true);
            auto material = make_material(m, p, {"name"});
            if (name) m_materials[*name] = {std::move(material), p};
        });
        for_list(doc, "lights", [&](const Json& l, const std::string& p) {
            if (!expect_object(l, p, "a light")) return;
            new_name(l, p, m_lights, Kind::light, false);
            if (l.contains("name") && l["name"].is_string()) m_lights[l["name"].get<std::string>()] = {nullptr, p};
            if (auto light = create(m_reg.lights, Kind::light, l, p, {"name"}))
                m_out.job.lights.push_back(std::move(light));
        });
        std::vector<SceneObject> objects;
        for_list(doc, "shapes", [&](const Json& s, const std::string& p) { read_shape(s, p, objects); });
        if (!doc.contains("shapes")) error("", "missing key 'shapes': a scene needs at least one shape");
        const std::optional<CameraSpec> camera = read_camera(doc);
        read_render(doc, camera);
        set_auto_levels();
        if (m_diag.empty()) {
            try {
                m_out.job.scene = std::make_shared<const Scene>(std::move(objects));
            } catch (const Error& e) {
                error("/shapes", e.what());
            }
        }
    }

    void read_plugins(const Json& doc) {
        for_list(doc, "plugins", [&](const Json& v, const std::string& p) {
            auto name = string(v, p);
            if (!name) return;
            if (name->empty() || name->find('/') != std::string::npos || name->find('\\') != std::string::npos ||
                ends_with_ci(*name, ".so") || name->front() == '.') {
                error(p, "'" + *name +
                             "' is not a plugin name: a scene names plugins by name only (\"myshader\"), "
                             "never by a path or a file name; they are found on the plugin search path (--plugin-dir)");
                return;
            }
            m_out.plugins.push_back(*name);
            if (!m_options.plugin_loader) {
                error(p, "the scene needs plugin '" + *name + "', but plugin loading is not available in this program");
                return;
            }
            try {
                m_options.plugin_loader(*name);
            } catch (const std::exception& e) {
                error(p, "plugin '" + *name + "': " + e.what());
            }
        });
    }

    std::optional<Mat4> read_transform(const Json& v, const std::string& p) {
        if (v.is_array()) {
            // A list of transforms, the first applied first.
            Mat4 m(1.0f);
            bool ok = true;
            for (std::size_t i = 0; i < v.size(); ++i) {
                auto step = read_transform_object(v[i], pointer_append(p, i));
                if (step)
                    m = *step * m;
                else
                    ok = false;
            }
            if (!ok) return std::nullopt;
            return m;
        }
        return read_transform_object(v, p);
    }

    std::optional<Mat4> read_transform_object(const Json& v, const std::string& p) {
        if (!expect_object(v, p, "a transform {\"translate\", \"rotate\", \"scale\"} or {\"matrix\"}"))
            return std::nullopt;
        check_keys(v, p, {"translate", "rotate", "scale", "matrix"});
        if (v.contains("matrix")) {
            if (v.contains("translate") || v.contains("rotate") || v.contains("scale")) {
                error(pointer_append(p, "matrix"), "give 'matrix' alone, or translate / rotate / scale without it");
                return std::nullopt;
            }
            return read_matrix(v["matrix"], pointer_append(p, "matrix"));
        }
        Vec3 translate(0.0f), rotate(0.0f), scale(1.0f);
        bool ok = true;
        if (v.contains("translate")) {
            if (auto x = vec3(v["translate"], pointer_append(p, "translate")))
                translate = *x;
            else
                ok = false;
        }
        if (v.contains("rotate")) {
            if (auto a = vec3(v["rotate"], pointer_append(p, "rotate")))
                rotate = *a;
            else
                ok = false;
        }
        if (v.contains("scale")) {
            const std::string sp = pointer_append(p, "scale");
            std::optional<Vec3> k;
            if (v["scale"].is_number())
                k = Vec3(v["scale"].get<float>());
            else
                k = vec3(v["scale"], sp);
            if (k && (!is_finite(*k) || k->x == 0.0f || k->y == 0.0f || k->z == 0.0f)) {
                error(sp, "a scale must be finite and non-zero, not " + v["scale"].dump());
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

    std::optional<Mat4> read_matrix(const Json& v, const std::string& p) {
        std::vector<double> values;
        if (v.is_array() && v.size() == 4 && std::all_of(v.begin(), v.end(), [](const Json& row) {
                return row.is_array() && row.size() == 4 &&
                       std::all_of(row.begin(), row.end(), [](const Json& x) { return x.is_number(); });
            })) {
            for (const Json& row : v)
                for (const Json& x : row) values.push_back(x.get<double>());
        } else if (v.is_array() && v.size() == 16 &&
                   std::all_of(v.begin(), v.end(), [](const Json& x) { return x.is_number(); })) {
            for (const Json& x : v) values.push_back(x.get<double>());
        } else {
            error(p, "expected a 4x4 matrix: 4 rows of 4 numbers, or 16 numbers row by row, not " + describe(v));
            return std::nullopt;
        }
        if (values[12] != 0.0 || values[13] != 0.0 || values[14] != 0.0 || values[15] != 1.0) {
            error(p, "the last row must be [0, 0, 0, 1] (an affine transform)");
            return std::nullopt;
        }
        Mat4 m(1.0f);
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col)
                m[col][row] = static_cast<float>(values[static_cast<std::size_t>(row * 4 + col)]);
        return m;
    }

    void read_shape(const Json& s, const std::string& p, std::vector<SceneObject>& objects) {
        if (!expect_object(s, p, "a shape")) return;
        auto name = new_name(s, p, m_shapes, Kind::shape, false);
        const std::string fallback_name = name ? *name : p;
        SurfaceFlags flags;
        bool visible = true, ok = true;
        if (s.contains("casts_shadows")) {
            if (auto b = boolean(s["casts_shadows"], pointer_append(p, "casts_shadows"))) flags.casts_shadows = *b;
        }
        if (s.contains("reversed")) {
            if (auto b = boolean(s["reversed"], pointer_append(p, "reversed"))) flags.reversed = *b;
        }
        if (s.contains("visible")) {
            if (auto b = boolean(s["visible"], pointer_append(p, "visible"))) visible = *b;
        }
        std::optional<Mat4> transform;
        if (s.contains("transform")) {
            transform = read_transform(s["transform"], pointer_append(p, "transform"));
            if (!transform) ok = false;
        }
        std::shared_ptr<const Material> material;
        if (s.contains("material")) {
            const std::string mp = pointer_append(p, "material");
            const Json& m = s["material"];
            if (m.is_string()) {
                auto it = m_materials.find(m.get<std::string>());
                if (it == m_materials.end()) {
                    error(mp, "no material named '" + m.get<std::string>() +
                                  "' (defined: " + join(keys_of(m_materials)) + ")");
                    ok = false;
                } else {
                    material = it->second.object;
                    ok = ok && material;
                }
            } else if (m.is_object()) {
                material = make_material(m, mp, {});
                ok = ok && material;
            } else {
                error(mp, "expected a material name or an inline material object, not " + describe(m));
                ok = false;
            }
        } else if (visible) {
            error(p, "missing key 'material' (only a shape with \"visible\": false, kept for instances, has none)");
            ok = false;
        }
        Params extra;
        const bool is_instance = s.contains("type") && s["type"] == "instance";
        if (is_instance && transform) {
            Params::List m;
            for (int row = 0; row < 4; ++row)
                for (int col = 0; col < 4; ++col) m.push_back((*transform)[col][row]);
            extra.set("matrix", std::move(m));
        }
        std::shared_ptr<const Shape> shape =
            create(m_reg.shapes, Kind::shape, s, p,
                   {"name", "material", "transform", "casts_shadows", "reversed", "visible"}, extra);
        if (shape && transform && !is_instance) {
            try {
                shape = std::make_shared<const Instance>(shape, *transform);
            } catch (const Error& e) {
                error(pointer_append(p, "transform"), e.what());
                shape = nullptr;
            }
        }
        if (name) m_shapes[*name] = {shape, p};
        if (!shape || !ok || !visible) return;
        if (auto it = m_material_uses.find(material.get()); it != m_material_uses.end()) {
            std::optional<UvFootprint> where;
            bool reported = false;
            for (const Texture* t : it->second) {
                auto a = m_auto_lod.find(t);
                if (a == m_auto_lod.end()) continue;
                if (!where) where = footprint(s, p, transform);
                if (where) {
                    a->second.users.push_back(*where);
                } else if (!reported) {
                    reported = true;
                    error(pointer_append(p, "material"),
                          "uses a texture with \"lod\": \"auto\", which is worked out for spheres and disks only, "
                          "not a '" +
                              s["type"].get<std::string>() + "'; give that texture a number as its lod");
                }
            }
        }
        objects.push_back({shape, material, flags, fallback_name});
    }

    std::optional<CameraSpec> read_camera(const Json& doc) {
        if (!doc.contains("camera")) {
            error("", "missing key 'camera'");
            return std::nullopt;
        }
        const Json& c = doc["camera"];
        const std::string p = "/camera";
        if (!expect_object(c, p, "a camera")) return std::nullopt;
        check_keys(c, p, {"type", "position", "look_at", "up", "fov", "aperture", "focus_distance"});
        CameraSpec spec;
        m_thin_lens = false;
        if (c.contains("type")) {
            if (auto t = string(c["type"], "/camera/type")) {
                if (*t == "thin_lens")
                    m_thin_lens = true;
                else if (*t != "pinhole")
                    error("/camera/type", "unknown camera type '" + *t + "'; known: pinhole, thin_lens");
            }
        }
        // A value that failed to read leaves its default, which could make a second, misleading error
        // ("eye and look_at must differ"): the camera is then not built.
        bool ok = true;
        if (c.contains("position")) {
            if (auto v = vec3(c["position"], "/camera/position"))
                spec.eye = *v;
            else
                ok = false;
        }
        if (c.contains("look_at")) {
            if (auto v = vec3(c["look_at"], "/camera/look_at"))
                spec.look_at = *v;
            else
                ok = false;
        }
        if (c.contains("up")) {
            if (auto v = vec3(c["up"], "/camera/up"))
                spec.up = *v;
            else
                ok = false;
        }
        if (c.contains("fov")) {
            if (auto v = number(c["fov"], "/camera/fov", 1e-3, 179.0))
                spec.vertical_fov_degrees = static_cast<float>(*v);
            else
                ok = false;
        }
        for (const char* key : {"aperture", "focus_distance"}) {
            if (!c.contains(key)) continue;
            const std::string kp = pointer_append(p, key);
            if (!m_thin_lens) {
                error(kp, std::string("'") + key + "' needs \"type\": \"thin_lens\"");
                continue;
            }
            if (auto v = number(c[key], kp, 0.0, 1e30))
                (key[0] == 'a' ? m_lens.aperture : m_lens.focus_distance) = static_cast<float>(*v);
            else
                ok = false;
        }
        if (!ok) return std::nullopt;
        return spec;
    }

    void read_render(const Json& doc, std::optional<CameraSpec> camera) {
        const std::string p = "/render";
        const Json empty = Json::object();
        const Json& r = doc.contains("render") ? doc["render"] : empty;
        if (!expect_object(r, p, "the render settings")) return;
        check_keys(r, p,
                   {"width", "height", "aa", "spp", "max_depth", "background", "skybox", "tonemap", "convention",
                    "seed", "output", "threads", "min_weight", "max_crossings"});
        const SceneOverrides& o = m_options.overrides;
        RenderSettings& settings = m_out.job.settings;
        WhittedOptions& whitted = m_out.job.whitted;
        auto at = [&](const char* key) { return pointer_append(p, key); };

        // Size: the file's (default 640 x 480), then the command line's; one side alone keeps the aspect ratio.
        std::int64_t width = 640, height = 480;
        bool size_ok = true;
        if (r.contains("width")) {
            if (auto v = integer(r["width"], at("width"), 1, kMaxImageSide))
                width = *v;
            else
                size_ok = false;
        }
        if (r.contains("height")) {
            if (auto v = integer(r["height"], at("height"), 1, kMaxImageSide))
                height = *v;
            else
                size_ok = false;
        }
        if (size_ok && (r.contains("width") || r.contains("height"))) {
            try {
                check_image_size(width, height, "image size");
            } catch (const Error& e) {
                error(at("width"), e.what());
                size_ok = false;
            }
        }
        if (o.width && !o.height)
            height = std::max<std::int64_t>(1, std::llround(static_cast<double>(height) * *o.width / width));
        if (o.height && !o.width)
            width = std::max<std::int64_t>(1, std::llround(static_cast<double>(width) * *o.height / height));
        if (o.width) width = *o.width;
        if (o.height) height = *o.height;
        if (o.width || o.height) {
            try {
                check_image_size(width, height, "--width/--height");
            } catch (const Error& e) {
                m_diag.error_at(0, e.what());
                size_ok = false;
            }
        }

        if (r.contains("aa")) {
            const Json& aa = r["aa"];
            if (aa.is_string()) {
                pattern(aa.get<std::string>(), at("aa"));
            } else if (aa.is_object()) {
                const std::string ap = at("aa");
                check_keys(aa, ap, {"mode", "max_depth", "threshold"});
                if (!aa.contains("mode"))
                    error(ap, "missing key 'mode' (none, grid, random, jittered or adaptive)");
                else if (auto m = string(aa["mode"], pointer_append(ap, "mode")))
                    pattern(*m, pointer_append(ap, "mode"));
                if (aa.contains("max_depth"))
                    if (auto v = integer(aa["max_depth"], pointer_append(ap, "max_depth"), 0, kMaxAdaptiveDepth))
                        settings.adaptive.max_depth = static_cast<int>(*v);
                if (aa.contains("threshold"))
                    if (auto v = number(aa["threshold"], pointer_append(ap, "threshold"), 0.0, 3.0))
                        settings.adaptive.threshold = static_cast<float>(*v);
            } else {
                error(at("aa"),
                      "expected a mode name or {\"mode\", \"max_depth\", \"threshold\"}, not " + describe(aa));
            }
        }
        if (o.aa) {
            try {
                settings.pattern = parse_pixel_pattern(*o.aa);
            } catch (const Error& e) {
                m_diag.error_at(0, std::string("--aa: ") + e.what());
            }
        }
        if (r.contains("spp"))
            if (auto v = integer(r["spp"], at("spp"), 1, kMaxSamplesPerPixel)) settings.spp = static_cast<int>(*v);
        if (o.spp) {
            if (*o.spp < 1 || *o.spp > kMaxSamplesPerPixel)
                m_diag.error_at(0, "--spp: must be in [1, " + std::to_string(kMaxSamplesPerPixel) + "], not " +
                                       std::to_string(*o.spp));
            else
                settings.spp = *o.spp;
        }
        if (r.contains("seed"))
            if (auto v = integer(r["seed"], at("seed"), 0, std::numeric_limits<std::int64_t>::max()))
                settings.seed = static_cast<std::uint64_t>(*v);
        if (o.seed) settings.seed = *o.seed;
        if (r.contains("threads"))
            if (auto v = integer(r["threads"], at("threads"), 0, 1024)) settings.threads = static_cast<int>(*v);
        if (o.threads) {
            if (*o.threads < 0 || *o.threads > 1024)
                m_diag.error_at(0, "--threads: must be in [0, 1024] (0: all cores)");
            else
                settings.threads = *o.threads;
        }
        if (r.contains("max_depth"))
            if (auto v = integer(r["max_depth"], at("max_depth"), 0, 100)) whitted.max_depth = static_cast<int>(*v);
        if (r.contains("min_weight"))
            if (auto v = number(r["min_weight"], at("min_weight"), 0.0, 1.0))
                whitted.min_weight = static_cast<float>(*v);
        if (r.contains("max_crossings"))
            if (auto v = integer(r["max_crossings"], at("max_crossings"), 0, 100000))
                whitted.max_crossings = static_cast<int>(*v);
        if (r.contains("convention")) {
            if (auto c = string(r["convention"], at("convention"))) {
                if (*c == "physical")
                    whitted.convention = Convention::physical;
                else if (*c == "classic")
                    whitted.convention = Convention::classic;
                else
                    error(at("convention"), "unknown convention '" + *c + "'; expected physical or classic");
            }
        }
        if (r.contains("background") && r.contains("skybox"))
            error(at("skybox"), "give 'background' or 'skybox', not both");
        if (r.contains("background"))
            if (auto c = colour(r["background"], at("background"))) whitted.background = *c;
        if (r.contains("skybox")) {
            const Json& sky = r["skybox"];
            if (sky.is_string()) {
                auto it = m_textures.find(sky.get<std::string>());
                if (it == m_textures.end())
                    error(at("skybox"), "no texture named '" + sky.get<std::string>() +
                                            "' (defined: " + join(keys_of(m_textures)) + ")");
                else
                    whitted.environment = it->second.object;
            } else if (sky.is_object()) {
                whitted.environment = make_texture(sky, at("skybox"), false);
            } else {
                error(at("skybox"), "expected a texture name or an inline texture (a cubemap), not " + describe(sky));
            }
            if (auto a = m_auto_lod.find(whitted.environment.get()); a != m_auto_lod.end())
                a->second.environment = true;
        }
        read_tonemap(r, at("tonemap"));
        if (r.contains("output")) {
            if (auto out = string(r["output"], at("output"))) {
                try {
                    output_format(*out);
                    m_out.output = fs::path(*out).is_absolute() ? fs::path(*out) : m_folder / *out;
                } catch (const Error& e) {
                    error(at("output"), e.what());
                }
            }
        }
        if (!camera || !size_ok) return;
        camera->width = static_cast<int>(width);
        camera->height = static_cast<int>(height);
        m_camera = camera;
        try {
            if (m_thin_lens)
                m_out.job.camera = std::make_shared<const ThinLensCamera>(*camera, m_lens);
            else
                m_out.job.camera = std::make_shared<const PinholeCamera>(*camera);
        } catch (const Error& e) {
            error("/camera", e.what());
        }
    }

    void pattern(const std::string& name, const std::string& p) {
        try {
            m_out.job.settings.pattern = parse_pixel_pattern(name);
        } catch (const Error& e) {
            error(p, e.what());
        }
    }

    void read_tonemap(const Json& r, const std::string& p) {
        std::string name = "none";
        Params params;
        const Json* obj = nullptr;
        if (r.contains("tonemap")) {
            const Json& t = r["tonemap"];
            if (t.is_string()) {
                name = t.get<std::string>();
            } else if (t.is_object()) {
                obj = &t;
                if (auto type = t.contains("type") ? string(t["type"], pointer_append(p, "type")) : std::nullopt)
                    name = *type;
                else if (!t.contains("type"))
                    error(p, "missing key 'type' (a tone operator name or none)");
                for (const auto& [key, value] : t.items()) {
                    if (key == "type") continue;
                    if (value.is_number())
                        params.set(key, value.get<double>());
                    else if (value.is_boolean())
                        params.set(key, value.get<bool>());
                    else if (value.is_string())
                        params.set(key, value.get<std::string>());
                    else
                        error(pointer_append(p, key),
                              "expected a number, a string or true/false, not " + describe(value));
                }
            } else {
                error(p, "expected a tone operator name or {\"type\": ..., parameters}, not " + describe(t));
                return;
            }
        }
        if (m_options.overrides.tonemap && *m_options.overrides.tonemap != name) {
            name = *m_options.overrides.tonemap;
            params = Params();  // the file's parameters belong to the file's operator
            obj = nullptr;
        }
        try {
            m_out.tone = make_tone_operator(m_reg.tone_operators, name, std::move(params));
            m_out.tone_name = name;
        } catch (const Error& e) {
            const std::string msg =
                std::string(e.what()) + (name == "none" ? "" : "; known: none, " + join(m_reg.tone_operators.names()));
            if (obj)
                factory_error(Kind::texture, name, *obj, p, e.what());
            else if (r.contains("tonemap") && !m_options.overrides.tonemap)
                error(p, msg);
            else
                m_diag.error_at(0, "--tonemap: " + msg);
        }
    }

    Diagnostics m_diag;
    fs::path m_folder;
    const SceneLoadOptions& m_options;
    SceneRegistries& m_reg;
    SearchPath m_search;
    std::map<Kind, std::set<std::string, std::less<>>> m_builtin;
    std::map<std::string, Named<Texture>> m_textures;
    std::map<std::string, Named<const Material>> m_materials;
    std::map<std::string, Named<const Light>> m_lights;
    std::map<std::string, Named<const Shape>> m_shapes;
    bool m_thin_lens = false;
    LensSpec m_lens;
    LoadedScene m_out;

    // "lod": "auto" textures and what they are seen on.
    struct AutoLevel {
        LevelOfDetail* levels;
        std::vector<UvFootprint> users;
        bool environment;
    };
    std::map<const Texture*, AutoLevel> m_auto_lod;
    std::map<const Texture*, std::vector<const Texture*>> m_texture_uses;
    std::map<const Material*, std::vector<const Texture*>> m_material_uses;
    std::vector<const Texture*>* m_collect = nullptr;  // the textures the object being made uses
    std::optional<CameraSpec> m_camera;                // with the final image size
};

SceneRegistries& builtin_registries() {
    static SceneRegistries registries = SceneRegistries::builtins();
    return registries;
}

}  // namespace

LoadedScene parse_scene(std::string_view text, const fs::path& file, const SceneLoadOptions& options) {
    SceneRegistries& registries = options.registries ? *options.registries : builtin_registries();
    Loader loader(file, options, registries);
    return loader.load(text);
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
