#pragma once
// rtlab-view's command line: the common flags of every rtlab app and its own.
#include <rtlab/app/command_line.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace rtlab::app {

struct ViewOptions {
    std::filesystem::path scene;
    CommonOptions common;  ///< -o: the file the save button writes; --aa: sobol or random
    /// --screenshot-after-passes N FILE: render N passes, save the window as PNG, exit.
    std::optional<int> screenshot_passes;
    std::filesystem::path screenshot_file;
    std::filesystem::path script;  ///< --script FILE: commands as on standard input
    bool commands_on_stdin = false;
    std::string integrator;          ///< --integrator (a common flag); empty: the scene's
    std::optional<double> exposure;  ///< stops
};

/// Parses the command line. Returns the exit status when the program should stop now (--help, a usage
/// error: 0 or 2), nothing when it should go on.
std::optional<int> parse_view_options(int argc, char** argv, ViewOptions& options);

}  // namespace rtlab::app
