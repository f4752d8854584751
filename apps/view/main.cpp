// rtlab-view SCENE.json [common flags] [--integrator NAME] [--exposure STOPS] [--script FILE | --stdin]
//   [--screenshot-after-passes N FILE]
// A window showing the scene rendering progressively, with tone controls, camera, pixel inspector and live
// reload. Exit status: 0 closed (or the screenshot written), 1 no display or a bad scene, 2 bad command line.
#include "options.hpp"
#include "viewer.hpp"

#include <rtlab/app/course_app.hpp>

int main(int argc, char** argv) {
    rtlab::app::ViewOptions options;
    if (auto status = rtlab::app::parse_view_options(argc, argv, options)) return *status;
    return rtlab::app::run_program("rtlab-view", [&] { return rtlab::view::run_viewer(options, argv[0]); });
}
