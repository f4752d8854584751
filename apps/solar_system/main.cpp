// rtlab-solar-system [--frames N] [--frame-range A:B] [--procedural] [--no-texture-filter] [common flags]:
// the textured solar system (apps/solar_system/scene.cpp), one picture or an orbiting-camera sequence.
#include "scene.hpp"
#include "sequence.hpp"

#include <rtlab/app/course_app.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/render/texture_level.hpp>

#include <fmt/core.h>

int main(int argc, char** argv) {
    CLI::App cli{"rtlab-solar-system: the Sun and eight textured planets, Saturn's rings, the star field"};
    rtlab::app::CourseOptions options;
    options.output = "solar-system.png";
    rtlab::app::add_course_options(cli, options);
    int frames = 0;
    std::string range;
    bool procedural = false, unfiltered = false;
    cli.add_option("--frames", frames, "render an orbiting-camera sequence of N frames to OUT-0000.EXT, ...")
        ->check(CLI::Range(1, 100000));
    cli.add_option("--frame-range", range, "with --frames: only frames A to B - 1 (to split a sequence)");
    cli.add_flag("--procedural", procedural, "procedural planet maps and star field even when the images are found");
    cli.add_flag("--no-texture-filter", unfiltered, "planet maps and sky at full resolution (shows the shimmer)");
    if (const auto status = rtlab::app::parse_command_line(cli, argc, argv)) return *status;
    return rtlab::app::run_app("rtlab-solar-system", [&] {
        if (!range.empty() && frames == 0) throw rtlab::Error("--frame-range needs --frames");
        const int count = std::max(frames, 1);
        const rtlab::solar::FrameRange r = rtlab::solar::parse_frame_range(range, count);
        (void)rtlab::output_format(options.output);  // a bad -o before the textures load, not after
        const auto data =
            rtlab::app::course_data_path(options, rtlab::app::executable_path(argv[0]), "rtlab-solar-system");
        const rtlab::solar::SolarAssets assets = rtlab::solar::load_solar_assets(data, procedural);
        if (!options.quiet) fmt::print("{}\n", assets.note);
        for (int f = r.first; f < r.last; ++f) {
            rtlab::solar::SolarView view{options.width, options.height, f, count, !unfiltered, 4.0f};
            // The settings first (the scene's and the flags'), for the samples the map levels allow for.
            rtlab::RenderJob job = rtlab::solar::make_solar_job(assets, view);
            rtlab::app::apply_course_options(options, job);
            const rtlab::RenderSettings& s = job.settings;
            view.samples_per_pixel = rtlab::filtering_samples(s);
            const rtlab::RenderSettings settings = job.settings;
            job = rtlab::solar::make_solar_job(assets, view);
            job.settings = settings;
            if (options.max_depth) job.whitted.max_depth = *options.max_depth;
            const auto output = frames > 0 ? rtlab::solar::numbered_path(options.output, f) : options.output;
            const auto label = frames > 0 ? fmt::format("solar frame {}/{}", f, count) : std::string("solar system");
            if (rtlab::app::run_course_render(job, options, output, label).interrupted) return 130;
        }
        return 0;
    });
}
