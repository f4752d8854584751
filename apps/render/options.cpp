#include "options.hpp"

#include <rtlab/tonemap/tone_operator.hpp>

namespace rtlab::app {

std::optional<int> parse_options(int argc, char** argv, RenderOptions& o) {
    CommandLine cli("rtlab-render",
                    "rtlab-render: render a JSON scene file (docs/scene-format.md) to PNG, EXR, HDR or PFM");
    std::string scene;
    cli.add_positional("scene", scene, "the scene file (.json)");
    cli.add_common(o.common, make_tone_registry().names());
    cli.add_list("--plugin", o.plugins.files, "plugin module to load (FILE.so); repeatable");
    cli.add_list("--plugin-dir", o.plugins.dirs, "folder in which the plugins a scene names are found; repeatable");
    cli.add_flag("--list", o.list, "print every registered type by category with its description, and exit");
    cli.add_flag("--verbose", o.verbose, "with --list: each type's parameters too");
    if (const auto status = cli.parse(argc, argv)) return status;
    if (o.verbose && !o.list) return cli.usage_error("--verbose goes with --list");
    if (!o.list && scene.empty()) return cli.usage_error("give a scene file (or --list); --help shows the options");
    o.scene = scene;
    return std::nullopt;
}

SceneOverrides scene_overrides(const CommonOptions& o) {
    SceneOverrides overrides;
    overrides.width = o.width;
    overrides.height = o.height;
    overrides.spp = o.spp;
    overrides.aa = o.aa;
    overrides.threads = o.threads;
    overrides.tonemap = o.tonemap;
    overrides.seed = o.seed;
    overrides.max_depth = o.max_depth;
    overrides.integrator = o.integrator;
    return overrides;
}

}  // namespace rtlab::app
