#pragma once
// rtlab-render's command line: the common flags of every rtlab app (rtlab/app/command_line.hpp) and its own.
#include <rtlab/app/command_line.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <filesystem>
#include <optional>
#include <vector>

namespace rtlab::app {

/// \brief The plugin modules asked for on the command line.
struct PluginOptions {
    std::vector<std::filesystem::path> files;  ///< --plugin FILE.so
    std::vector<std::filesystem::path> dirs;   ///< --plugin-dir DIR: where scenes' plugin names are found
};

struct RenderOptions {
    std::filesystem::path scene;
    CommonOptions common;  ///< common.output empty: the scene's render.output
    PluginOptions plugins;
    bool list = false;
    bool verbose = false;  ///< with --list: every type's parameters too
};

/// Parses the command line. Returns the exit status when the program should stop now (--help, a usage
/// error: 0 or 2), nothing when it should go on.
std::optional<int> parse_options(int argc, char** argv, RenderOptions& options);

/// What the loader takes from the command line: size, sampling, threads, tone operator, seed.
SceneOverrides scene_overrides(const CommonOptions& options);

}  // namespace rtlab::app
