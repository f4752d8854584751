#pragma once
// Private to the scene loader: objects made by the registries from a JSON object, by the declarations of
// their types. Stage 2 (each value checked against its key's declaration and turned into a parameter) and
// stage 3 (the registry's factory called, its errors placed at the keys they name) of loading a scene.
#include <rtlab/core/param_spec.hpp>
#include <rtlab/core/registry.hpp>

#include "load_context.hpp"

#include <exception>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rtlab::scene_detail {

/// What the loader adds to, or keeps from, the keys a type declares.
struct BuildOptions {
    std::vector<std::string> loader_keys;  ///< keys the loader reads itself ("name", "material", ...)
    std::vector<std::string> left_out;     ///< declared keys not passed on (a texture's files, when it falls back)
    Params extra;                          ///< parameters the loader sets (an instance's matrix)
    /// Parameters the loader set from a key of another name ("bake" from "fallback"): a factory's error
    /// about the parameter is shown at that key.
    std::map<std::string, std::string> written_as;
};

/// The object's "type", checked against the registered names; nullopt (reported) when missing or unknown.
std::optional<std::string> read_type(LoadContext& ctx, const std::vector<std::string>& known, Kind kind,
                                     const Json& obj, const std::string& p);

/// Every key of `obj` checked against `spec` and converted into `params`; false when any is wrong (reported).
bool read_params(LoadContext& ctx, const TypeSpec& spec, Kind kind, const std::string& type, const Json& obj,
                 const std::string& p, const BuildOptions& options, Params& params);

/// One value by its declaration; false when it is wrong (reported at p).
bool convert_param(LoadContext& ctx, const ParamSpec& spec, const Json& v, const std::string& p, Params& params);

/// A factory's exception, reported at the key it names (rtlab::ParamError) or at the object.
void report_build_error(LoadContext& ctx, Kind kind, const std::string& type, const Json& obj, const std::string& p,
                        const std::exception& e, const BuildOptions& options = {});

template <class Base>
std::shared_ptr<Base> build_object(LoadContext& ctx, const Registry<Base>& registry, Kind kind, const Json& obj,
                                   const std::string& p, const BuildOptions& options = {}) {
    const auto type = read_type(ctx, registry.names(), kind, obj, p);
    if (!type) return nullptr;
    Params params = options.extra;
    if (!read_params(ctx, registry.spec(*type), kind, *type, obj, p, options, params)) return nullptr;
    params.set_warning_sink([&ctx, p](const std::string& message) { ctx.warn(p, message); });
    try {
        auto object = registry.create(*type, std::move(params));
        if (!object) ctx.error(p, std::string(kind_name(kind)) + " type '" + *type + "' made nothing");
        return object;
    } catch (const std::exception& e) {
        report_build_error(ctx, kind, *type, obj, p, e, options);
    }
    return nullptr;
}

}  // namespace rtlab::scene_detail
