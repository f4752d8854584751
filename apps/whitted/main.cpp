// rtlab-whitted [-o OUT] [common flags]: renders the 1980 Whitted scene (apps/whitted/scene.cpp).
// Exit status: 0 rendered, 1 failed write, 2 bad command line, 130 stopped by Ctrl-C (what was rendered is written).
#include "scene.hpp"

#include <rtlab/app/course_app.hpp>

int main(int argc, char** argv) {
    rtlab::app::CommandLine cli(
        "rtlab-whitted", "rtlab-whitted: the 1980 Whitted scene (mirror sphere, hollow glass sphere, checkerboard)");
    rtlab::app::CourseOptions options;
    options.output = "whitted.png";
    options.width = 640;
    options.height = 480;
    rtlab::app::add_course_options(cli, options);
    if (const auto status = cli.parse(argc, argv)) return *status;
    return rtlab::app::run_program(cli.program(), [&] {
        rtlab::app::prepare_output(options.output);
        // The scene reads no data file, but --data-dir is a common flag: a folder that is not there is still
        // worth a warning, as in every app.
        (void)rtlab::app::course_data_path(options, rtlab::app::executable_path(argv[0]), "rtlab-whitted");
        rtlab::RenderJob job = rtlab::whitted::make_whitted_job(*options.width, *options.height);
        rtlab::app::apply_course_options(options, job);
        return rtlab::app::run_course_render(job, options, options.output, "whitted").interrupted
                   ? rtlab::app::kExitInterrupted
                   : rtlab::app::kExitDone;
    });
}
