// rtlab-render SCENE.json -o OUT.{png,exr,hdr,pfm} [common flags of every rtlab app: --width W --height H --aa MODE
//   --spp N --aa-threshold T --aa-depth D --depth D --threads N --seed N --tonemap OP --quiet --data-dir DIR...]
//   [--plugin FILE.so]... [--plugin-dir DIR]... | --list [--verbose]
// Exit status: 0 rendered, 1 bad scene or failed write (nothing written), 2 bad command line, 130 stopped by
// Ctrl-C (what was rendered is written).
#include <rtlab/app/course_app.hpp>
#include <rtlab/app/progress_bar.hpp>
#include <rtlab/app/stop_on_interrupt.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/param_spec.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/scene/plugin.hpp>
#include <rtlab/scene/scene_loader.hpp>
#include <rtlab/scene/type_listing.hpp>

#include <fmt/core.h>

#include <cstdio>
#include <string>

#include "options.hpp"

namespace {

int run(const rtlab::app::RenderOptions& options, const char* argv0) {
    const rtlab::app::CommonOptions& common = options.common;
    rtlab::SceneRegistries registries = rtlab::SceneRegistries::builtins();
    rtlab::PluginHost plugins(registries.materials, registries.textures, registries.lights,
                              rtlab::plugin_search_path(options.plugins.dirs));
    for (const auto& file : options.plugins.files) plugins.load_file(file);
    if (options.list) {
        fmt::print("{}", rtlab::list_types(registries, options.verbose));
        fmt::print("tone operator none: clamps to [0, 1] (the default)\n");
        return rtlab::app::kExitDone;
    }
    // A missing folder in -o is found before the scene loads, not after the render.
    if (!common.output.empty()) rtlab::app::prepare_output(common.output);
    rtlab::SceneLoadOptions load;
    load.data_path = rtlab::app::app_data_path(common.data_dirs, rtlab::app::executable_path(argv0), "rtlab-render");
    load.registries = &registries;
    const std::string context = options.scene.string() + ": plugins";
    load.plugin_loader = [&](const std::string& name) { plugins.load_by_name(name, context); };
    load.overrides = rtlab::app::scene_overrides(common);
    // The meshes' kd-trees are built while loading: on the --threads given, as the render runs (a thread count
    // set in the scene file alone is known only once it is loaded, so that build uses every core).
    rtlab::LoadedScene scene;
    rtlab::app::run_with_threads(common.threads_or_all(), [&] { scene = rtlab::load_scene(options.scene, load); });
    rtlab::RenderSettings& settings = scene.job.settings;
    if (common.aa_threshold) settings.adaptive.threshold = *common.aa_threshold;
    if (common.aa_depth) settings.adaptive.max_depth = *common.aa_depth;
    if (common.max_depth) scene.job.whitted.max_depth = *common.max_depth;
    rtlab::app::check_sampling(settings, common);
    const std::filesystem::path output = common.output.empty() ? scene.output : common.output;
    if (output.empty()) throw rtlab::Error(options.scene.string() + ": no output: give -o FILE or render.output");
    const rtlab::OutputFormat format = rtlab::output_format(output);  // an unknown extension fails now
    rtlab::app::prepare_output(output);
    for (const auto& w : scene.warnings) fmt::print(stderr, "rtlab-render: warning: {}\n", w);
    if (!common.quiet && !scene.assets.empty()) fmt::print("{}\n", rtlab::describe_sources(scene.assets));

    rtlab::app::StopOnInterrupt interrupt;
    rtlab::app::ProgressBar bar(stderr, common.quiet);
    rtlab::RenderCallbacks callbacks;
    callbacks.stop = &interrupt.flag();
    if (bar.enabled()) callbacks.progress = [&bar](const rtlab::RenderProgress& p) { bar.update(p); };
    const rtlab::RenderResult result = rtlab::render_job(scene.job, callbacks);
    bar.finish();
    rtlab::ToneReport report;
    rtlab::write_render_output(result.image, output, scene.tone.get(), &report);
    if (!common.quiet) {
        const rtlab::RenderStats& s = result.stats;
        // spp means nothing to adaptive sampling: its own settings instead.
        const std::string sampling =
            settings.pattern == rtlab::PixelPattern::adaptive
                ? fmt::format("depth {} threshold {}", settings.adaptive.max_depth, settings.adaptive.threshold)
                : fmt::format("spp {}", settings.spp);
        fmt::print("{}: {}x{}, {} objects ({}), {} lights{}, aa {} {}\n", options.scene.string(), result.image.width(),
                   result.image.height(), scene.job.scene->object_count(), scene.job.scene->structure(),
                   scene.job.lights.size(), scene.job.environment ? " and an environment" : "",
                   rtlab::pixel_pattern_name(settings.pattern), sampling);
        fmt::print("rays: {} camera, {} shadow, {} reflected, {} refracted; {} total in {:.3f} s, {:.3g} rays/s\n",
                   s.rays.camera, s.rays.shadow, s.rays.reflected, s.rays.refracted, s.rays.total(), s.seconds,
                   s.rays_per_second());
        // Only PNG output is tone-mapped; the linear formats keep the rendered values.
        if (scene.tone && format == rtlab::OutputFormat::png)
            fmt::print("tone: {}\n", report.summary);
        else if (scene.tone)
            fmt::print("tone: {} not applied: {} keeps linear values\n", scene.tone_name, output.extension().string());
        fmt::print("{} {}{}\n", s.cancelled ? "stopped; wrote what was rendered to" : "wrote", output.string(),
                   s.cancelled ? fmt::format(" ({} of {} tiles)", s.tiles_done, s.tiles_total) : "");
    }
    if (common.quiet && result.stats.cancelled)
        fmt::print(stderr, "rtlab-render: stopped; wrote what was rendered to {}\n", output.string());
    return result.stats.cancelled ? rtlab::app::kExitInterrupted : rtlab::app::kExitDone;
}

}  // namespace

int main(int argc, char** argv) {
    rtlab::app::RenderOptions options;
    if (auto status = rtlab::app::parse_options(argc, argv, options)) return *status;
    return rtlab::app::run_program("rtlab-render", [&] { return run(options, argv[0]); });
}
