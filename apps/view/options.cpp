#include "options.hpp"

#include <rtlab/tonemap/tone_operator.hpp>

namespace rtlab::app {

std::optional<int> parse_view_options(int argc, char** argv, ViewOptions& o) {
    CommandLine cli("rtlab-view", "rtlab-view: show a JSON scene file rendering progressively, in a window");
    std::string scene, script;
    cli.add_positional("scene", scene, "the scene file (.json)");
    cli.add_common(o.common, make_tone_registry().names());
    // Two values after one flag (the form the project's checks use): CLI11 directly, checked below as the layer's
    // typed helpers check theirs.
    std::vector<std::string> shot;
    cli.app()
        .add_option("--screenshot-after-passes", shot,
                    "N FILE: render N passes, save the whole window as PNG to FILE and exit")
        ->expected(2);
    cli.add_text("--script", script, "a file of commands, run as if typed on standard input");
    cli.add_flag("--stdin", o.commands_on_stdin,
                 "read commands from standard input (listed in apps/view/commands.hpp)");
    cli.add_number("--exposure", o.exposure, -64, 64, "exposure in stops");
    if (const auto status = cli.parse(argc, argv)) return status;
    if (scene.empty()) return cli.usage_error("give a scene file; --help shows the options");
    // The viewer samples progressively: only the two sequences of the progressive renderer make sense.
    if (o.common.aa && *o.common.aa != "sobol" && *o.common.aa != "random")
        return cli.usage_error("--aa: the viewer renders progressively: sobol or random, not '" + *o.common.aa + "'");
    if (o.common.aa_threshold || o.common.aa_depth)
        return cli.usage_error("--aa-threshold and --aa-depth are for adaptive sampling, which the viewer does not do");
    if (!shot.empty()) {
        try {
            std::size_t used = 0;
            const int n = std::stoi(shot[0], &used);
            if (used != shot[0].size() || n < 1 || n > 65536) throw std::invalid_argument("range");
            o.screenshot_passes = n;
        } catch (const std::exception&) {
            return cli.usage_error("--screenshot-after-passes: N must be a whole number in [1, 65536], not '" +
                                   shot[0] + "'");
        }
        o.screenshot_file = shot[1];
    }
    o.scene = scene;
    o.script = script;
    o.integrator = o.common.integrator.value_or("");
    return std::nullopt;
}

}  // namespace rtlab::app
