// rtlab-whitted [-o OUT] [common flags]: renders the 1980 Whitted scene (apps/whitted/scene.cpp).
#include "scene.hpp"

#include <rtlab/app/course_app.hpp>

int main(int argc, char** argv) {
    CLI::App cli{"rtlab-whitted: the 1980 Whitted scene (mirror sphere, hollow glass sphere, checkerboard)"};
    rtlab::app::CourseOptions options;
    options.output = "whitted.png";
    rtlab::app::add_course_options(cli, options);
    if (const auto status = rtlab::app::parse_command_line(cli, argc, argv)) return *status;
    return rtlab::app::run_app("rtlab-whitted", [&] {
        // The scene reads no data file, but --data-dir is a common flag: a folder that is not there is still
        // worth a warning, as in every app.
        (void)rtlab::app::course_data_path(options, rtlab::app::executable_path(argv[0]), "rtlab-whitted");
        rtlab::RenderJob job = rtlab::whitted::make_whitted_job(options.width, options.height);
        rtlab::app::apply_course_options(options, job);
        return rtlab::app::run_course_render(job, options, options.output, "whitted").interrupted ? 130 : 0;
    });
}
