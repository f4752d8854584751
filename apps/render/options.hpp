#pragma once
// rtlab-render's command line.
#include <rtlab/scene/scene_loader.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::app {

/// \brief The plugin modules asked for on the command line.
struct PluginOptions {
    std::vector<std::filesystem::path> files;  ///< --plugin FILE.so
    std::vector<std::filesystem::path> dirs;   ///< --plugin-dir DIR: where scenes' plugin names are found
};

struct RenderOptions {
    std::filesystem::path scene;
    std::filesystem::path output;  ///< empty: the scene's render.output
    SceneOverrides overrides;
    std::vector<std::filesystem::path> data_dirs;
    PluginOptions plugins;
    bool quiet = false;
    bool list = false;
};

/// Parses the command line. Returns the exit status when the program should stop now (--help, a usage
/// error: 0 or 2), nothing when it should go on.
std::optional<int> parse_options(int argc, char** argv, RenderOptions& options);

}  // namespace rtlab::app
