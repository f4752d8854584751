#include "settings_reader.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/core/spelling.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/render/thin_lens_camera.hpp>

#include "json_values.hpp"
#include "object_builder.hpp"
#include "texture_reader.hpp"

#include <cmath>
#include <limits>

namespace rtlab::scene_detail {

namespace fs = std::filesystem;

namespace {

void read_pattern(LoadContext& ctx, const std::string& name, const std::string& p) {
    try {
        ctx.out.job.settings.pattern = parse_pixel_pattern(name);
    } catch (const Error& e) {
        ctx.error(p, e.what());
    }
}

void read_aa(LoadContext& ctx, const Json& aa, const std::string& ap) {
    RenderSettings& settings = ctx.out.job.settings;
    if (aa.is_string()) return read_pattern(ctx, aa.get<std::string>(), ap);
    if (!aa.is_object()) {
        ctx.error(ap, "expected a mode name or {\"mode\", \"max_depth\", \"threshold\"}, not " + describe(aa));
        return;
    }
    check_keys(ctx.diag, aa, ap, {"mode", "max_depth", "threshold"});
    if (!aa.contains("mode"))
        ctx.error(ap, "missing key 'mode' (none, grid, random, jittered, sobol or adaptive)");
    else if (auto m = read_string(ctx.diag, aa["mode"], pointer_append(ap, "mode")))
        read_pattern(ctx, *m, pointer_append(ap, "mode"));
    if (aa.contains("max_depth"))
        if (auto v = read_integer(ctx.diag, aa["max_depth"], pointer_append(ap, "max_depth"), 0, kMaxAdaptiveDepth))
            settings.adaptive.max_depth = static_cast<int>(*v);
    if (aa.contains("threshold"))
        if (auto v = read_number(ctx.diag, aa["threshold"], pointer_append(ap, "threshold"), 0.0, 3.0))
            settings.adaptive.threshold = static_cast<float>(*v);
}

// Width and height: the file's (default 640 x 480), then the command line's; one side alone keeps the
// aspect ratio. False when they are wrong (reported).
bool read_size(LoadContext& ctx, const Json& r, const std::string& p, std::int64_t& width, std::int64_t& height) {
    bool ok = true;
    for (const char* key : {"width", "height"}) {
        if (!r.contains(key)) continue;
        if (auto v = read_integer(ctx.diag, r[key], pointer_append(p, key), 1, kMaxImageSide))
            (key[0] == 'w' ? width : height) = *v;
        else
            ok = false;
    }
    if (ok && (r.contains("width") || r.contains("height"))) {
        try {
            check_image_size(width, height, "image size");
        } catch (const Error& e) {
            ctx.error(pointer_append(p, "width"), e.what());
            ok = false;
        }
    }
    const SceneOverrides& o = ctx.options.overrides;
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
            ctx.diag.error_at(0, e.what());
            ok = false;
        }
    }
    return ok;
}

// spp means exactly that many samples: a pattern on a square grid given another count is told so, not rounded.
void check_square_count(LoadContext& ctx, const RenderSettings& settings, const std::string& p) {
    if (settings.pattern != PixelPattern::grid && settings.pattern != PixelPattern::jittered) return;
    int below = 1;
    while ((below + 1) * (below + 1) <= settings.spp) ++below;
    if (below * below == settings.spp) return;
    ctx.error(p, std::to_string(settings.spp) + " samples are not a square number, which " +
                     std::string(pixel_pattern_name(settings.pattern)) + " needs: give " +
                     std::to_string(below * below) + " or " + std::to_string((below + 1) * (below + 1)) +
                     ", or use \"random\" or \"sobol\" for any count");
}

void read_sampling(LoadContext& ctx, const Json& r, const std::string& p) {
    const SceneOverrides& o = ctx.options.overrides;
    RenderSettings& settings = ctx.out.job.settings;
    auto at = [&](const char* key) { return pointer_append(p, key); };
    if (r.contains("aa")) read_aa(ctx, r["aa"], at("aa"));
    if (o.aa) {
        try {
            settings.pattern = parse_pixel_pattern(*o.aa);
        } catch (const Error& e) {
            ctx.diag.error_at(0, std::string("--aa: ") + e.what());
        }
    }
    if (r.contains("spp")) {
        if (auto v = read_integer(ctx.diag, r["spp"], at("spp"), 1, kMaxSamplesPerPixel))
            settings.spp = static_cast<int>(*v);
        if (!o.spp) check_square_count(ctx, settings, at("spp"));
    }
    // The command line checks its own values; a program passing overrides directly is told here.
    if (o.spp && (*o.spp < 1 || *o.spp > kMaxSamplesPerPixel))
        ctx.diag.error_at(
            0, "--spp: must be in [1, " + std::to_string(kMaxSamplesPerPixel) + "], not " + std::to_string(*o.spp));
    else if (o.spp)
        settings.spp = *o.spp;
    if (r.contains("seed"))
        if (auto v = read_integer(ctx.diag, r["seed"], at("seed"), 0, std::numeric_limits<std::int64_t>::max()))
            settings.seed = static_cast<std::uint64_t>(*v);
    if (o.seed) settings.seed = *o.seed;
    if (r.contains("threads"))
        if (auto v = read_integer(ctx.diag, r["threads"], at("threads"), 0, 1024))
            settings.threads = static_cast<int>(*v);
    if (o.threads && (*o.threads < 0 || *o.threads > 1024))
        ctx.diag.error_at(0, "--threads: must be in [0, 1024] (0: all cores)");
    else if (o.threads)
        settings.threads = *o.threads;
}

const std::vector<std::string> kIntegrators{"whitted", "direct", "path", "photon", "sppm"};

// render.photons: the photon mappers' settings (PhotonOptions).
void read_photons(LoadContext& ctx, const Json& r, const std::string& p) {
    if (!r.contains("photons")) return;
    const Json& j = r["photons"];
    const std::string jp = pointer_append(p, "photons");
    if (!expect_object(ctx.diag, j, jp, "the photon mapping settings")) return;
    check_keys(ctx.diag, j, jp, {"count", "nearest", "max_radius", "gather", "filter", "radius", "alpha"});
    PhotonOptions& o = ctx.out.job.photons;
    auto at = [&](const char* key) { return pointer_append(jp, key); };
    if (j.contains("count"))
        if (auto v = read_integer(ctx.diag, j["count"], at("count"), 1, 1 << 30))
            o.photons = static_cast<std::uint32_t>(*v);
    if (j.contains("nearest"))
        if (auto v = read_integer(ctx.diag, j["nearest"], at("nearest"), 1, 100000)) o.nearest = static_cast<int>(*v);
    if (j.contains("max_radius"))
        if (auto v = read_number(ctx.diag, j["max_radius"], at("max_radius"), 0.0, 1e30))
            o.max_radius = static_cast<float>(*v);
    if (j.contains("gather"))
        if (auto v = read_integer(ctx.diag, j["gather"], at("gather"), 0, 4096)) o.gather = static_cast<int>(*v);
    if (j.contains("filter")) {
        if (auto name = read_string(ctx.diag, j["filter"], at("filter"))) {
            if (auto f = parse_photon_filter(*name))
                o.filter = *f;
            else
                ctx.error(at("filter"), "unknown filter '" + *name + "'" +
                                            did_you_mean(*name, {"box", "cone", "epanechnikov"}) +
                                            "; expected box, cone or epanechnikov");
        }
    }
    if (j.contains("radius"))
        if (auto v = read_number(ctx.diag, j["radius"], at("radius"), 0.0, 1e30)) o.radius = static_cast<float>(*v);
    if (j.contains("alpha")) {
        if (auto v = read_number(ctx.diag, j["alpha"], at("alpha"), 0.0, 1.0)) {
            if (*v > 0.0 && *v < 1.0)
                o.alpha = static_cast<float>(*v);
            else
                ctx.error(at("alpha"), "must be in (0, 1), not " + std::to_string(*v));
        }
    }
}

void read_whitted(LoadContext& ctx, const Json& r, const std::string& p) {
    WhittedOptions& whitted = ctx.out.job.whitted;
    auto at = [&](const char* key) { return pointer_append(p, key); };
    PathOptions& path = ctx.out.job.path;
    // One depth for every integrator: Whitted's reflections and refractions, the path tracer's bounces.
    if (r.contains("max_depth"))
        if (auto v = read_integer(ctx.diag, r["max_depth"], at("max_depth"), 0, 100))
            whitted.max_depth = path.max_depth = static_cast<int>(*v);
    if (ctx.options.overrides.max_depth) whitted.max_depth = path.max_depth = *ctx.options.overrides.max_depth;
    if (r.contains("roulette_depth"))
        if (auto v = read_integer(ctx.diag, r["roulette_depth"], at("roulette_depth"), 0, 100))
            path.roulette_depth = static_cast<int>(*v);
    auto read_kind = [&](const std::string& name, const std::string& where) {
        if (auto kind = parse_integrator(name))
            ctx.out.job.integrator = *kind;
        else if (where.empty())
            ctx.diag.error_at(0, "--integrator: unknown integrator '" + name + "'" + did_you_mean(name, kIntegrators) +
                                     "; expected whitted, direct, path, photon or sppm");
        else
            ctx.error(where, "unknown integrator '" + name + "'" + did_you_mean(name, kIntegrators) +
                                 "; expected whitted, direct, path, photon or sppm");
    };
    if (r.contains("integrator"))
        if (auto name = read_string(ctx.diag, r["integrator"], at("integrator"))) read_kind(*name, at("integrator"));
    if (ctx.options.overrides.integrator) read_kind(*ctx.options.overrides.integrator, "");
    read_photons(ctx, r, p);
    if (r.contains("min_weight"))
        if (auto v = read_number(ctx.diag, r["min_weight"], at("min_weight"), 0.0, 1.0))
            whitted.min_weight = static_cast<float>(*v);
    if (r.contains("max_crossings"))
        if (auto v = read_integer(ctx.diag, r["max_crossings"], at("max_crossings"), 0, 100000))
            whitted.max_crossings = static_cast<int>(*v);
    if (r.contains("convention")) {
        if (auto c = read_string(ctx.diag, r["convention"], at("convention"))) {
            if (*c == "physical")
                whitted.convention = Convention::physical;
            else if (*c == "classic")
                whitted.convention = Convention::classic;
            else
                ctx.error(at("convention"), "unknown convention '" + *c + "'" +
                                                did_you_mean(*c, {"physical", "classic"}) +
                                                "; expected physical or classic");
        }
    }
    if (r.contains("background") && r.contains("skybox"))
        ctx.error(at("skybox"), "give 'background' or 'skybox', not both");
    for (const char* other : {"background", "skybox"})
        if (r.contains("environment") && r.contains(other))
            ctx.error(at("environment"), std::string("give 'environment' or '") + other + "', not both");
    if (r.contains("background"))
        if (auto c = read_colour(ctx.diag, r["background"], at("background"))) whitted.background = *c;
    if (r.contains("environment")) {
        const Json& e = r["environment"];
        if (expect_object(ctx.diag, e, at("environment"), "an environment ({\"type\": \"envmap\", ...})"))
            ctx.out.job.environment =
                build_object(ctx, ctx.registries.environments, Kind::environment, e, at("environment"));
    }
    if (!r.contains("skybox")) return;
    const Json& sky = r["skybox"];
    if (sky.is_string()) {
        auto it = ctx.textures.find(sky.get<std::string>());
        if (it == ctx.textures.end())
            ctx.error(at("skybox"), "no texture named '" + sky.get<std::string>() +
                                        "' (defined: " + join(names_of(ctx.textures)) + ")");
        else
            whitted.environment = it->second.object;
    } else if (sky.is_object()) {
        whitted.environment = read_texture(ctx, sky, at("skybox"), false);
    } else {
        ctx.error(at("skybox"), "expected a texture name or an inline texture (a cubemap), not " + describe(sky));
    }
    if (auto a = ctx.auto_levels.find(whitted.environment.get()); a != ctx.auto_levels.end())
        a->second.environment = true;
}

void read_tonemap(LoadContext& ctx, const Json& r, const std::string& p) {
    const ToneRegistry& registry = ctx.registries.tone_operators;
    const auto& o = ctx.options.overrides;
    std::string name = "none";
    Params params;
    const Json* obj = nullptr;
    bool ok = true;
    if (r.contains("tonemap")) {
        const Json& t = r["tonemap"];
        if (t.is_string()) {
            name = t.get<std::string>();
        } else if (t.is_object()) {
            obj = &t;
            std::vector<std::string> known = registry.names();
            known.insert(known.begin(), "none");
            if (auto type = read_type(ctx, known, Kind::tone, t, p)) {
                name = *type;
                if (name != "none") ok = read_params(ctx, registry.spec(name), Kind::tone, name, t, p, {}, params);
            } else {
                ok = false;
            }
        } else {
            ctx.error(p, "expected a tone operator name or {\"type\": ..., parameters}, not " + describe(t));
            return;
        }
    }
    if (o.tonemap && *o.tonemap != name) {
        name = *o.tonemap;
        params = Params();  // the file's parameters belong to the file's operator
        obj = nullptr;
        ok = true;
    }
    if (!ok) return;
    try {
        ctx.out.tone = make_tone_operator(registry, name, std::move(params));
        ctx.out.tone_name = name;
    } catch (const std::exception& e) {
        const std::string known = "none, " + join(registry.names());
        if (obj)
            report_build_error(ctx, Kind::tone, name, *obj, p, e);
        else if (o.tonemap)
            ctx.diag.error_at(0, "--tonemap: unknown tone operator '" + name + "'; known: " + known);
        else
            ctx.error(
                p, "unknown tone operator '" + name + "'" + did_you_mean(name, registry.names()) + "; known: " + known);
    }
}

}  // namespace

std::optional<CameraRead> read_camera(LoadContext& ctx, const Json& doc) {
    if (!doc.contains("camera")) {
        ctx.error("", "missing key 'camera'");
        return std::nullopt;
    }
    const Json& c = doc["camera"];
    const std::string p = "/camera";
    if (!expect_object(ctx.diag, c, p, "a camera")) return std::nullopt;
    check_keys(ctx.diag, c, p, {"type", "position", "look_at", "up", "fov", "aperture", "focus_distance"});
    CameraRead out;
    if (c.contains("type")) {
        if (auto t = read_string(ctx.diag, c["type"], "/camera/type")) {
            if (*t == "thin_lens")
                out.thin_lens = true;
            else if (*t != "pinhole")
                ctx.error("/camera/type", "unknown camera type '" + *t + "'" +
                                              did_you_mean(*t, {"pinhole", "thin_lens"}) +
                                              "; known: pinhole, thin_lens");
        }
    }
    // A value that failed to read leaves its default, which could make a second, misleading error ("eye and
    // look_at must differ"): the camera is then not built.
    bool ok = true;
    const std::pair<const char*, Vec3*> points[] = {
        {"position", &out.spec.eye}, {"look_at", &out.spec.look_at}, {"up", &out.spec.up}};
    for (const auto& [key, target] : points) {
        if (!c.contains(key)) continue;
        if (auto v = read_vec3(ctx.diag, c[key], pointer_append(p, key)))
            *target = *v;
        else
            ok = false;
    }
    if (c.contains("fov")) {
        if (auto v = read_number(ctx.diag, c["fov"], "/camera/fov", 1e-3, 179.0))
            out.spec.vertical_fov_degrees = static_cast<float>(*v);
        else
            ok = false;
    }
    for (const char* key : {"aperture", "focus_distance"}) {
        if (!c.contains(key)) continue;
        const std::string kp = pointer_append(p, key);
        if (!out.thin_lens) {
            ctx.error(kp, std::string("'") + key + "' needs \"type\": \"thin_lens\"");
            continue;
        }
        if (auto v = read_number(ctx.diag, c[key], kp, 0.0, 1e30))
            (key[0] == 'a' ? out.lens.aperture : out.lens.focus_distance) = static_cast<float>(*v);
        else
            ok = false;
    }
    if (!ok) return std::nullopt;
    return out;
}

void read_render(LoadContext& ctx, const Json& doc, const std::optional<CameraRead>& camera) {
    const std::string p = "/render";
    const Json empty = Json::object();
    const Json& r = doc.contains("render") ? doc["render"] : empty;
    if (!expect_object(ctx.diag, r, p, "the render settings")) return;
    check_keys(
        ctx.diag, r, p,
        {"width", "height", "aa", "spp", "max_depth", "background", "skybox", "environment", "tonemap", "convention",
         "seed", "output", "threads", "min_weight", "max_crossings", "integrator", "roulette_depth", "photons"});
    std::int64_t width = 640, height = 480;
    const bool size_ok = read_size(ctx, r, p, width, height);
    read_sampling(ctx, r, p);
    read_whitted(ctx, r, p);
    read_tonemap(ctx, r, pointer_append(p, "tonemap"));
    if (r.contains("output")) {
        const std::string op = pointer_append(p, "output");
        if (auto out = read_string(ctx.diag, r["output"], op)) {
            try {
                output_format(*out);
                ctx.out.output = fs::path(*out).is_absolute() ? fs::path(*out) : ctx.folder() / *out;
            } catch (const Error& e) {
                ctx.error(op, e.what());
            }
        }
    }
    if (!camera || !size_ok) return;
    CameraSpec spec = camera->spec;
    spec.width = static_cast<int>(width);
    spec.height = static_cast<int>(height);
    ctx.camera = spec;
    try {
        if (camera->thin_lens)
            ctx.out.job.camera = std::make_shared<const ThinLensCamera>(spec, camera->lens);
        else
            ctx.out.job.camera = std::make_shared<const PinholeCamera>(spec);
    } catch (const Error& e) {
        ctx.error("/camera", e.what());
    }
}

}  // namespace rtlab::scene_detail
