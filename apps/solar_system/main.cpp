// rtlab-solar-system [--frames N] [--frame-range A:B] [--procedural] [--no-texture-filter] [common flags]:
// the textured solar system (apps/solar_system/scene.cpp), one picture or an orbiting-camera sequence.
#include "scene.hpp"
#include "sequence.hpp"

#include <rtlab/app/course_app.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/render/texture_level.hpp>

#include <fmt/core.h>

int main(int argc, char** argv) {
    rtlab::app::CommandLine cli(
        "rtlab-solar-system", "rtlab-solar-system: the Sun and eight textured planets, Saturn's rings, the star field");
    rtlab::app::CourseOptions options;
    options.output = "solar-system.png";
    options.width = 640;
    options.height = 480;
    rtlab::app::add_course_options(cli, options);
    std::optional<int> frames;
    std::string range;
    bool procedural = false, unfiltered = false;
    cli.add_integer("--frames", frames, 1, 100000,
                    "render an orbiting-camera sequence of N frames to OUT-0000.EXT, ...");
    cli.add_text("--frame-range", range, "with --frames: only frames A to B - 1 (to split a sequence)");
    cli.add_flag("--procedural", procedural, "procedural planet maps and star field even when the images are found");
    cli.add_flag("--no-texture-filter", unfiltered, "planet maps and sky at full resolution (shows the shimmer)");
    if (const auto status = cli.parse(argc, argv)) return *status;
    return rtlab::app::run_program(cli.program(), [&] {
        if (!range.empty() && !frames) throw rtlab::app::UsageError("--frame-range needs --frames");
        const int count = frames.value_or(1);
        rtlab::solar::FrameRange r;
        try {
            r = rtlab::solar::parse_frame_range(range, count);
        } catch (const rtlab::Error& e) {
            throw rtlab::app::UsageError(e.what());  // names --frame-range already
        }
        rtlab::app::prepare_output(options.output);  // before the textures load, not after the render
        const auto data =
            rtlab::app::course_data_path(options, rtlab::app::executable_path(argv[0]), "rtlab-solar-system");
        const rtlab::solar::SolarAssets assets = rtlab::solar::load_solar_assets(data, procedural);
        if (!options.quiet) fmt::print("{}\n", assets.note);
        for (int f = r.first; f < r.last; ++f) {
            rtlab::solar::SolarView view{*options.width, *options.height, f, count, !unfiltered, 4.0f};
            // The settings first (the scene's and the flags'), for the samples the map levels allow for.
            rtlab::RenderJob job = rtlab::solar::make_solar_job(assets, view);
            rtlab::app::apply_course_options(options, job);
            const rtlab::RenderSettings& s = job.settings;
            view.samples_per_pixel = rtlab::filtering_samples(s);
            const rtlab::RenderSettings settings = job.settings;
            job = rtlab::solar::make_solar_job(assets, view);
            job.settings = settings;
            if (options.max_depth) job.whitted.max_depth = *options.max_depth;
            const auto output = frames ? rtlab::solar::numbered_path(options.output, f) : options.output;
            const auto label = frames ? fmt::format("solar frame {}/{}", f, count) : std::string("solar system");
            if (rtlab::app::run_course_render(job, options, output, label).interrupted)
                return rtlab::app::kExitInterrupted;
        }
        return rtlab::app::kExitDone;
    });
}
