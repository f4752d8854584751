#pragma once
// The window: GLFW + Dear ImGui around the image view, the render worker, live reload and the commands.
#include "options.hpp"

namespace rtlab::view {

/// Runs the window until it is closed, `quit` or the screenshot is written. Returns the exit status.
int run_viewer(const app::ViewOptions& options, const char* argv0);

}  // namespace rtlab::view
