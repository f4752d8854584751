#include "object_builder.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/core/spelling.hpp>

#include "json_values.hpp"
#include "texture_reader.hpp"

#include <algorithm>

namespace rtlab::scene_detail {

namespace {

bool contains(const std::vector<std::string>& list, const std::string& s) {
    return std::find(list.begin(), list.end(), s) != list.end();
}

bool all_numbers(const Json& v) {
    return std::all_of(v.begin(), v.end(), [](const Json& x) { return x.is_number(); });
}

Params::List numbers_of(const Json& v) {
    Params::List list;
    for (const Json& x : v) list.push_back(x.get<double>());
    return list;
}

// A texture's name, or an inline texture: the object, noted as used by what is being built.
bool texture_value(LoadContext& ctx, const ParamSpec& spec, const Json& v, const std::string& p, Params& params) {
    std::shared_ptr<Texture> texture;
    if (v.is_object()) {
        texture = read_texture(ctx, v, p, false);
        if (!texture) return false;
    } else {
        const std::string name = v.get<std::string>();
        auto it = ctx.textures.find(name);
        if (it == ctx.textures.end()) {
            ctx.error(p, "no texture named '" + name + "'" + did_you_mean(name, names_of(ctx.textures)) +
                             "; expected a colour (a number or [r, g, b]) or the name of a texture defined earlier "
                             "in /textures (defined: " +
                             join(names_of(ctx.textures)) + ")");
            return false;
        }
        if (!it->second.object) return false;  // its own error is already reported
        texture = it->second.object;
    }
    ctx.note_use(texture.get());
    params.set_object<Texture>(spec.name, std::move(texture));
    return true;
}

}  // namespace

std::optional<std::string> read_type(LoadContext& ctx, const std::vector<std::string>& known, Kind kind,
                                     const Json& obj, const std::string& p) {
    if (!obj.contains("type")) {
        ctx.error(p, "missing key 'type'; expected one of: " + join(known));
        return std::nullopt;
    }
    auto type = read_string(ctx.diag, obj["type"], pointer_append(p, "type"));
    if (!type) return std::nullopt;
    if (!contains(known, *type)) {
        ctx.error(pointer_append(p, "type"), "unknown " + std::string(kind_name(kind)) + " type '" + *type + "'" +
                                                 did_you_mean(*type, known) + "; known: " + join(known));
        return std::nullopt;
    }
    return type;
}

bool convert_param(LoadContext& ctx, const ParamSpec& spec, const Json& v, const std::string& p, Params& params) {
    Diagnostics& diag = ctx.diag;
    switch (spec.kind) {
        case ParamKind::number:
            if (auto x = read_number(diag, v, p, spec.lo, spec.hi)) return params.set(spec.name, *x), true;
            return false;
        case ParamKind::integer: {
            const auto lo = static_cast<std::int64_t>(std::max(spec.lo, -9.0e15));
            const auto hi = static_cast<std::int64_t>(std::min(spec.hi, 9.0e15));
            if (auto n = read_integer(diag, v, p, lo, hi)) return params.set(spec.name, static_cast<double>(*n)), true;
            return false;
        }
        case ParamKind::boolean:
            if (auto b = read_boolean(diag, v, p)) return params.set(spec.name, *b), true;
            return false;
        case ParamKind::colour:
            if (!read_colour(diag, v, p)) return false;
            params.set(spec.name, v.is_number() ? Params::Value(v.get<double>()) : Params::Value(numbers_of(v)));
            return true;
        case ParamKind::vector:
            if (!read_vec3(diag, v, p)) return false;
            params.set(spec.name, numbers_of(v));
            return true;
        case ParamKind::numbers:
            if (v.is_number()) return params.set(spec.name, v.get<double>()), true;
            if (v.is_array() && all_numbers(v)) return params.set(spec.name, numbers_of(v)), true;
            ctx.error(p, "expected a number or a list of numbers, not " + describe(v));
            return false;
        case ParamKind::texture:
        case ParamKind::scalar:
            if (v.is_number()) return params.set(spec.name, v.get<double>()), true;
            if (v.is_array() && all_numbers(v)) return params.set(spec.name, numbers_of(v)), true;
            if (v.is_string() || v.is_object()) return texture_value(ctx, spec, v, p, params);
            ctx.error(p, std::string(spec.kind == ParamKind::texture ? "expected a colour (a number or [r, g, b])"
                                                                     : "expected a number") +
                             ", a texture's name or an inline texture, not " + describe(v));
            return false;
        case ParamKind::file:
        case ParamKind::folder: {
            auto name = read_string(diag, v, p);
            if (!name) return false;
            auto found = spec.kind == ParamKind::file ? ctx.find_file(*name, p) : ctx.find_folder(*name, p);
            if (found) params.set(spec.name, *found);
            return found.has_value();
        }
        case ParamKind::word: {
            auto word = read_string(diag, v, p);
            if (!word) return false;
            if (!spec.words.empty() && !contains(spec.words, *word)) {
                ctx.error(p, "unknown value '" + *word + "' for '" + spec.name + "'" + did_you_mean(*word, spec.words) +
                                 "; expected one of: " + join(spec.words));
                return false;
            }
            params.set(spec.name, *word);
            return true;
        }
        case ParamKind::text:
            if (auto s = read_string(diag, v, p)) return params.set(spec.name, *s), true;
            return false;
        case ParamKind::shape: {
            auto name = read_string(diag, v, p);
            if (!name) return false;
            auto it = ctx.shapes.find(*name);
            if (it == ctx.shapes.end()) {
                ctx.error(p, "no shape named '" + *name + "'" + did_you_mean(*name, names_of(ctx.shapes)) +
                                 " defined earlier in /shapes (named shapes: " + join(names_of(ctx.shapes)) + ")");
                return false;
            }
            if (!it->second.object) return false;
            params.set_object<const Shape>(spec.name, it->second.object);
            return true;
        }
    }
    return false;
}

bool read_params(LoadContext& ctx, const TypeSpec& spec, Kind kind, const std::string& type, const Json& obj,
                 const std::string& p, const BuildOptions& options, Params& params) {
    bool ok = true;
    for (const auto& [key, value] : obj.items()) {
        if (key == "type" || contains(options.loader_keys, key) || contains(options.left_out, key)) continue;
        const ParamSpec* param = spec.find(key);
        if (!param) {
            std::vector<std::string> keys = spec.names();
            keys.insert(keys.end(), options.loader_keys.begin(), options.loader_keys.end());
            ctx.error(pointer_append(p, key), "unknown key '" + key + "' for " + kind_name(kind) + " type '" + type +
                                                  "'" + did_you_mean(key, keys) +
                                                  " (rtlab-render --list --verbose shows each type's keys)");
            ok = false;
            continue;
        }
        ok = convert_param(ctx, *param, value, pointer_append(p, key), params) && ok;
    }
    for (const ParamSpec& param : spec.params()) {
        if (!param.required || obj.contains(param.name) || params.has(param.name) ||
            contains(options.left_out, param.name))
            continue;
        ctx.error(p, "missing key '" + param.name + "' for " + kind_name(kind) + " type '" + type + "' (" +
                         describe_param(param) + ")");
        ok = false;
    }
    return ok;
}

void report_build_error(LoadContext& ctx, Kind kind, const std::string& type, const Json& obj, const std::string& p,
                        const std::exception& e, const BuildOptions& options) {
    const auto* param = dynamic_cast<const ParamError*>(&e);
    if (!param) {
        if (dynamic_cast<const Error*>(&e))
            ctx.error(p, e.what());
        else
            ctx.error(p, std::string(kind_name(kind)) + " type '" + type + "' failed: " + e.what());
        return;
    }
    if (param->reason() == ParamError::Reason::unused) {
        // The declaration names a key the factory did not read: the type's own bug, shown where the key is.
        for (const std::string& key : param->keys())
            ctx.error(obj.contains(key) ? pointer_append(p, key) : p,
                      "key '" + key + "' is declared by " + kind_name(kind) + " type '" + type + "' but not used");
        return;
    }
    std::string key = param->keys().empty() ? std::string() : param->keys().front();
    if (auto it = options.written_as.find(key); it != options.written_as.end()) key = it->second;
    ctx.error(!key.empty() && obj.contains(key) ? pointer_append(p, key) : p, e.what());
}

}  // namespace rtlab::scene_detail
