// rtlab-render SCENE.json -o OUT.{png,exr,hdr,pfm} [common flags of every rtlab app: --width W --height H --aa MODE
//   --spp N --aa-threshold T --aa-depth D --depth D --threads N --seed N --tonemap OP --quiet --data-dir DIR...]
//   [--noise E] [--time S] [--uniform] [--variance] [--plugin FILE.so]... [--plugin-dir DIR]... | --list [--verbose]
// rtlab-render SCENE.json --sample-range A:B -o SHARE.rtshare [...]: one share of a frame, for rtlab-merge.
// rtlab-render SCENE.json ... --record-rays NAME --record-out PREFIX [--record-max N]: also the rays the object NAME
//   answers, in its shape's own space, into PREFIX.closest.rays and PREFIX.shadow.rays (one render thread).
// Exit status: 0 rendered, 1 bad scene or failed write (nothing written), 2 bad command line, 130 stopped by
// Ctrl-C (what was rendered is written).
#include <rtlab/accel/ray_io.hpp>
#include <rtlab/app/course_app.hpp>
#include <rtlab/app/progress_bar.hpp>
#include <rtlab/app/stop_on_interrupt.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/param_spec.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/render/noise_target.hpp>
#include <rtlab/render/ray_recorder.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sample_share.hpp>
#include <rtlab/scene/plugin.hpp>
#include <rtlab/scene/scene_loader.hpp>
#include <rtlab/scene/type_listing.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "options.hpp"
#include "scene_hash.hpp"

namespace {

using rtlab::app::UsageError;

/// The progressive renderer's settings for the job: its seed, threads and tiles.
rtlab::ProgressiveSettings progressive_settings(const rtlab::RenderSettings& s) {
    rtlab::ProgressiveSettings p;
    p.sequence = rtlab::SampleSequence::sobol;
    p.spp = s.spp;
    p.seed = s.seed;
    p.tile_size = s.tile_size;
    p.threads = s.threads;
    p.packets = s.packets;
    return p;
}

/// What --noise, --time and --sample-range need of the scene: the progressive pattern (and for a noise target, an
/// integrator whose half-images see all its error).
void check_progressive(const rtlab::app::RenderOptions& options, const rtlab::LoadedScene& scene) {
    const rtlab::RenderSettings& s = scene.job.settings;
    const std::string flag = options.sample_range ? "--sample-range" : (options.noise ? "--noise" : "--time");
    if (s.pattern != rtlab::PixelPattern::sobol)
        throw UsageError(flag + " needs the progressive pattern: add --aa sobol (" +
                         (options.common.aa ? "--aa " : "the scene's anti-aliasing is ") +
                         std::string(rtlab::pixel_pattern_name(s.pattern)) + ")");
    if (options.sample_range && scene.job.integrator == rtlab::IntegratorKind::sppm)
        throw UsageError(flag +
                         ": an sppm iteration builds on the ones before it, so its samples cannot be shared "
                         "out; use path, direct, whitted or photon");
    if (!options.sample_range && !rtlab::supports_noise_target(scene.job.integrator))
        throw UsageError(flag + ": the " + std::string(rtlab::integrator_name(scene.job.integrator)) +
                         " integrator is biased in a way the half-image estimate cannot see; use path or direct");
}

std::filesystem::path record_file(const rtlab::app::RecordOptions& record, const char* kind) {
    return record.prefix.string() + "." + kind + ".rays";
}

/// --record-rays: the named object's shape under a recorder, the scene built again around it, one render thread.
/// Both files are written (empty) first, so that a path that cannot be written fails before the render.
std::shared_ptr<rtlab::RayRecorder> start_recording(const rtlab::app::RecordOptions& record,
                                                    rtlab::LoadedScene& scene) {
    std::vector<rtlab::SceneObject> objects = scene.job.scene->objects();
    std::shared_ptr<rtlab::RayRecorder> recorder;
    try {
        recorder = rtlab::record_object_rays(
            objects, record.object, static_cast<std::size_t>(record.max.value_or(rtlab::app::kDefaultRecordMax)));
    } catch (const rtlab::Error& e) {
        throw rtlab::Error("--record-rays " + record.object + ": " + e.what());
    }
    for (const char* kind : {"closest", "shadow"}) {
        try {
            rtlab::app::prepare_output(record_file(record, kind));
            rtlab::write_ray_file(record_file(record, kind), {});
        } catch (const rtlab::Error& e) {
            throw rtlab::Error("--record-out " + record.prefix.string() + ": " + e.what());
        }
    }
    scene.job.scene = std::make_shared<const rtlab::Scene>(std::move(objects));
    scene.job.settings.threads = 1;
    return recorder;
}

/// Writes the recorded rays (what there is, after Ctrl-C too) and says what they are.
void finish_recording(const rtlab::app::RecordOptions& record, const rtlab::RayRecorder& recorder, bool quiet) {
    rtlab::write_ray_file(record_file(record, "closest"), recorder.closest_rays());
    rtlab::write_ray_file(record_file(record, "shadow"), recorder.shadow_rays());
    if (quiet) return;
    const auto line = [&](const char* kind, const rtlab::RayRecorder::Counts& c, std::size_t positive,
                          const char* positive_name, const char* file) {
        const double share = c.kept == 0 ? 0.0 : 100.0 * static_cast<double>(positive) / static_cast<double>(c.kept);
        fmt::print("recorded {}: {} {} queries, {} overlapping its bounds; wrote {} ({:.1f}% {}) to {}{}\n",
                   record.object, c.answered, kind, c.overlapping, c.kept, share, positive_name,
                   record_file(record, file).string(),
                   c.kept < c.overlapping ? fmt::format(" (--record-max {}: {} more not written)",
                                                        recorder.max_per_kind(), c.overlapping - c.kept)
                                          : "");
    };
    const auto& answers = recorder.closest_answers();
    const auto hits = static_cast<std::size_t>(std::count_if(
        answers.begin(), answers.end(), [](const rtlab::RayRecorder::Answer& a) { return a.t < rtlab::kInfinity; }));
    const auto& blocked = recorder.shadow_blocked();
    const auto blockers = static_cast<std::size_t>(std::count(blocked.begin(), blocked.end(), 1));
    line("closest-hit", recorder.closest_counts(), hits, "hit", "closest");
    line("shadow", recorder.shadow_counts(), blockers, "blocked", "shadow");
}

/// One share of the frame: samples [A, B) of every pixel into a .rtshare file.
int render_share(const rtlab::app::RenderOptions& options, const rtlab::LoadedScene& scene,
                 const std::filesystem::path& output, const rtlab::RenderCallbacks& base) {
    check_progressive(options, scene);
    const rtlab::app::SampleRange range = *options.sample_range;
    const std::uint64_t hash = rtlab::app::scene_hash(options.scene, scene, options.plugins.files);
    rtlab::ProgressiveSettings p = progressive_settings(scene.job.settings);
    p.first_sample = range.first;
    p.spp = static_cast<int>(range.end - range.first);
    rtlab::ProgressiveCallbacks callbacks;
    callbacks.progress = base.progress;
    callbacks.stop = base.stop;
    const auto radiance = rtlab::make_radiance_source(scene.job, scene.job.integrator, base.stop);
    const rtlab::ShareRenderResult r = rtlab::render_share(*scene.job.camera, *radiance, p, hash, output, callbacks);
    const bool stopped = r.end < range.end;
    if (!options.common.quiet || stopped) {
        std::FILE* out = options.common.quiet ? stderr : stdout;
        if (!r.written)
            fmt::print(out, "rtlab-render: stopped before the first block of {} samples was done: no share written\n",
                       rtlab::kDefaultBlockSamples);
        else
            fmt::print(out, "{}samples {} to {} of {}x{} pixels (scene hash {:016x}, seed {}) to {}{}\n",
                       stopped ? "rtlab-render: stopped; wrote " : "wrote ", range.first, r.end - 1,
                       scene.job.camera->width(), scene.job.camera->height(), hash, p.seed, output.string(),
                       stopped ? fmt::format(" (asked for {} to {})", range.first, range.end - 1) : "");
    }
    if (!options.common.quiet) {
        const rtlab::RenderStats& s = r.stats;
        fmt::print("rays: {} camera, {} shadow, {} reflected, {} refracted; {} total in {:.3f} s, {:.3g} rays/s\n",
                   s.rays.camera, s.rays.shadow, s.rays.reflected, s.rays.refracted, s.rays.total(), s.seconds,
                   s.rays_per_second());
    }
    return stopped ? rtlab::app::kExitInterrupted : rtlab::app::kExitDone;
}

/// Renders to --noise or --time: progressive passes of the halves sequence (rtlab/render/noise_target.hpp).
rtlab::RenderResult render_target(const rtlab::app::RenderOptions& options, const rtlab::LoadedScene& scene,
                                  const rtlab::RenderCallbacks& base, rtlab::TargetResult& target) {
    check_progressive(options, scene);
    rtlab::ProgressiveSettings p = progressive_settings(scene.job.settings);
    p.sequence = rtlab::SampleSequence::sobol_halves;
    rtlab::TargetSettings t;
    t.noise = options.noise.value_or(0.0);
    t.seconds = options.seconds.value_or(0.0);
    t.adaptive = !options.uniform;
    rtlab::ProgressiveCallbacks callbacks;
    callbacks.progress = base.progress;
    callbacks.stop = base.stop;
    const auto radiance = rtlab::make_radiance_source(scene.job, scene.job.integrator, base.stop);
    target = rtlab::render_to_target(*scene.job.camera, *radiance, p, t, callbacks);
    rtlab::RenderResult result;
    result.image = std::move(target.image);
    result.samples = target.buffer.counts();
    result.stats = target.stats;
    result.buffer = std::make_shared<const rtlab::SampleBuffer>(std::move(target.buffer));
    return result;
}

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
    if (common.no_packets) settings.packets = false;
    rtlab::app::check_sampling(settings, common);
    const std::filesystem::path output = common.output.empty() ? scene.output : common.output;
    if (output.empty()) throw rtlab::Error(options.scene.string() + ": no output: give -o FILE or render.output");
    const std::shared_ptr<rtlab::RayRecorder> recorder =
        options.record.object.empty() ? nullptr : start_recording(options.record, scene);
    if (options.sample_range) {
        rtlab::app::prepare_output(output);
        for (const auto& w : scene.warnings) fmt::print(stderr, "rtlab-render: warning: {}\n", w);
        rtlab::app::StopOnInterrupt interrupt;
        rtlab::app::ProgressBar bar(stderr, common.quiet);
        rtlab::RenderCallbacks callbacks;
        callbacks.stop = &interrupt.flag();
        if (bar.enabled()) callbacks.progress = [&bar](const rtlab::RenderProgress& p) { bar.update(p); };
        const int status = render_share(options, scene, output, callbacks);
        bar.finish();
        if (recorder) finish_recording(options.record, *recorder, common.quiet);
        return status;
    }
    const rtlab::OutputFormat format = rtlab::output_format(output);  // an unknown extension fails now
    if (options.variance && format != rtlab::OutputFormat::exr)
        throw UsageError("--variance needs EXR output, and the scene's render.output is " + output.string());
    if (options.variance && settings.pattern != rtlab::PixelPattern::sobol && !options.noise && !options.seconds)
        throw UsageError("--variance needs the progressive pattern, whose sums give the variance: add --aa sobol");
    rtlab::app::prepare_output(output);
    for (const auto& w : scene.warnings) fmt::print(stderr, "rtlab-render: warning: {}\n", w);
    if (!common.quiet && !scene.assets.empty()) fmt::print("{}\n", rtlab::describe_sources(scene.assets));

    rtlab::app::StopOnInterrupt interrupt;
    rtlab::app::ProgressBar bar(stderr, common.quiet);
    rtlab::RenderCallbacks callbacks;
    callbacks.stop = &interrupt.flag();
    if (bar.enabled()) callbacks.progress = [&bar](const rtlab::RenderProgress& p) { bar.update(p); };
    rtlab::TargetResult target;
    const bool to_target = options.noise || options.seconds;
    const rtlab::RenderResult result =
        to_target ? render_target(options, scene, callbacks, target) : rtlab::render_job(scene.job, callbacks);
    bar.finish();
    rtlab::ToneReport report;
    const rtlab::Image variance = options.variance ? result.buffer->mean_variance_image() : rtlab::Image();
    rtlab::write_render_output(result.image, output, scene.tone.get(), &report, options.variance ? &variance : nullptr);
    if (!common.quiet) {
        const rtlab::RenderStats& s = result.stats;
        // spp means nothing to adaptive sampling: its own settings instead.
        std::string sampling =
            settings.pattern == rtlab::PixelPattern::adaptive
                ? fmt::format("depth {} threshold {}", settings.adaptive.max_depth, settings.adaptive.threshold)
                : fmt::format("spp {}", settings.spp);
        if (to_target) sampling = fmt::format("spp at most {}", settings.spp);
        fmt::print("{}: {}x{}, {} objects ({}), {} lights{}, aa {} {}\n", options.scene.string(), result.image.width(),
                   result.image.height(), scene.job.scene->object_count(), scene.job.scene->structure(),
                   scene.job.lights.size(), scene.job.environment ? " and an environment" : "",
                   rtlab::pixel_pattern_name(settings.pattern), sampling);
        fmt::print("rays: {} camera, {} shadow, {} reflected, {} refracted; {} total in {:.3f} s, {:.3g} rays/s\n",
                   s.rays.camera, s.rays.shadow, s.rays.reflected, s.rays.refracted, s.rays.total(), s.seconds,
                   s.rays_per_second());
        if (to_target) {
            const rtlab::SampleBuffer& b = *result.buffer;
            const std::vector<std::uint32_t>& counts = result.samples;
            const auto [lo, hi] = std::minmax_element(counts.begin(), counts.end());
            fmt::print(
                "target: {} after {} passes: estimated relMSE {:.4g}{}; samples {} ({:.4g} per pixel, {} to {}; "
                "{})\n",
                rtlab::target_stop_name(target.stop), target.passes, target.estimate,
                options.noise ? fmt::format(" (target {:.4g})", *options.noise) : "", b.total_samples(),
                static_cast<double>(b.total_samples()) / static_cast<double>(counts.size()), *lo, *hi,
                options.uniform ? "uniform" : "adaptive");
        }
        // Only PNG output is tone-mapped; the linear formats keep the rendered values.
        if (scene.tone && format == rtlab::OutputFormat::png)
            fmt::print("tone: {}\n", report.summary);
        else if (scene.tone)
            fmt::print("tone: {} not applied: {} keeps linear values\n", scene.tone_name, output.extension().string());
        fmt::print("{} {}{}\n", s.cancelled ? "stopped; wrote what was rendered to" : "wrote", output.string(),
                   s.cancelled ? fmt::format(" ({} of {} tiles)", s.tiles_done, s.tiles_total) : "");
    }
    if (recorder) finish_recording(options.record, *recorder, common.quiet);
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
