// rtlab-render SCENE.json -o OUT.{png,exr,hdr,pfm} [--width W --height H] [--spp N] [--aa MODE] [--threads N]
//   [--tonemap OP] [--seed N] [--data-dir DIR]... [--plugin FILE.so]... [--plugin-dir DIR]... [--quiet] | --list
// Exit status: 0 rendered, 1 bad scene or failed write (nothing written), 2 usage, 130 stopped by Ctrl-C (what
// was rendered is written).
#include <rtlab/app/course_app.hpp>
#include <rtlab/app/progress_bar.hpp>
#include <rtlab/app/stop_on_interrupt.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/scene/plugin.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <fmt/core.h>

#include <cstdio>
#include <exception>

#include "options.hpp"

namespace {

template <class Registry>
void list_category(const char* title, const Registry& registry) {
    fmt::print("{}:\n", title);
    for (const auto& name : registry.names()) fmt::print("  {:<20} {}\n", name, registry.doc(name));
}

void list_types(const rtlab::SceneRegistries& r) {
    list_category("shapes", r.shapes);
    list_category("materials", r.materials);
    list_category("textures", r.textures);
    list_category("lights", r.lights);
    fmt::print("tone operators:\n  {:<20} {}\n", "none", "clamps to [0, 1] (the default)");
    for (const auto& name : r.tone_operators.names()) fmt::print("  {:<20} {}\n", name, r.tone_operators.doc(name));
}

int run(const rtlab::app::RenderOptions& options) {
    rtlab::SceneRegistries registries = rtlab::SceneRegistries::builtins();
    rtlab::PluginHost plugins(registries.materials, registries.textures, registries.lights,
                              rtlab::plugin_search_path(options.plugins.dirs));
    for (const auto& file : options.plugins.files) plugins.load_file(file);
    if (options.list) {
        list_types(registries);
        return 0;
    }
    rtlab::SceneLoadOptions load;
    load.data_dirs = options.data_dirs;
    load.registries = &registries;
    const std::string context = options.scene.string() + ": plugins";
    load.plugin_loader = [&](const std::string& name) { plugins.load_by_name(name, context); };
    load.overrides = options.overrides;
    // The meshes' kd-trees are built while loading: on the --threads given, as the render runs (a thread count
    // set in the scene file alone is known only once it is loaded, so that build uses every core).
    rtlab::LoadedScene scene;
    rtlab::app::run_with_threads(options.overrides.threads.value_or(0),
                                 [&] { scene = rtlab::load_scene(options.scene, load); });
    const std::filesystem::path output = options.output.empty() ? scene.output : options.output;
    if (output.empty()) throw rtlab::Error(options.scene.string() + ": no output: give -o FILE or render.output");
    rtlab::output_format(output);  // an unknown extension fails before the render, not after
    for (const auto& w : scene.warnings) fmt::print(stderr, "rtlab-render: warning: {}\n", w);

    rtlab::app::StopOnInterrupt interrupt;
    rtlab::app::ProgressBar bar(stderr, options.quiet);
    rtlab::RenderCallbacks callbacks;
    callbacks.stop = &interrupt.flag();
    if (bar.enabled()) callbacks.progress = [&bar](const rtlab::RenderProgress& p) { bar.update(p); };
    const rtlab::RenderResult result = rtlab::render_job(scene.job, callbacks);
    bar.finish();
    rtlab::ToneReport report;
    rtlab::write_render_output(result.image, output, scene.tone.get(), &report);
    if (!options.quiet) {
        const rtlab::RenderStats& s = result.stats;
        fmt::print("{}: {}x{}, {} objects ({}), {} lights, aa {} spp {}\n", options.scene.string(),
                   result.image.width(), result.image.height(), scene.job.scene->object_count(),
                   scene.job.scene->structure(), scene.job.lights.size(),
                   rtlab::pixel_pattern_name(scene.job.settings.pattern), scene.job.settings.spp);
        fmt::print("rays: {} camera, {} shadow, {} reflected, {} refracted; {} total in {:.3f} s, {:.3g} rays/s\n",
                   s.rays.camera, s.rays.shadow, s.rays.reflected, s.rays.refracted, s.rays.total(), s.seconds,
                   s.rays_per_second());
        if (scene.tone) fmt::print("tone: {}\n", report.summary);
        fmt::print("{} {}{}\n", s.cancelled ? "stopped; wrote what was rendered to" : "wrote", output.string(),
                   s.cancelled ? fmt::format(" ({} of {} tiles)", s.tiles_done, s.tiles_total) : "");
    }
    if (options.quiet && result.stats.cancelled)
        fmt::print(stderr, "rtlab-render: stopped; wrote what was rendered to {}\n", output.string());
    return result.stats.cancelled ? 130 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    rtlab::app::RenderOptions options;
    if (auto status = rtlab::app::parse_options(argc, argv, options)) return *status;
    try {
        return run(options);
    } catch (const std::exception& e) {
        fmt::print(stderr, "rtlab-render: {}\n", e.what());
        return 1;
    }
}
