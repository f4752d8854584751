#pragma once
/// \brief The apps' render progress line on stderr: only on a terminal, never with --quiet.
#include <rtlab/render/renderer.hpp>

#include <chrono>
#include <cstdio>
#include <string>

namespace rtlab::app {

/// One line without a newline: "[#######.............]  12/40 tiles  3.21 Mrays/s  0:05 elapsed  0:12 left".
/// The time left is extrapolated from the tiles done (shown as --:-- before the first).
std::string format_progress(const RenderProgress& progress, int bar_width = 30);

/// \brief Redraws format_progress in place with a carriage return.
class ProgressBar {
public:
    /// Draws on `out` only when `quiet` is false and `out` is a terminal (isatty), so piped or redirected
    /// output stays clean.
    ProgressBar(std::FILE* out, bool quiet);
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;
    ~ProgressBar();

    bool enabled() const { return m_enabled; }
    /// Takes RenderCallbacks::progress's calls (one at a time); redraws at most every 100 ms and for the
    /// last tile.
    void update(const RenderProgress& progress);
    /// Ends the line if anything was drawn; called by the destructor too.
    void finish();

private:
    std::FILE* m_out;
    bool m_enabled;
    bool m_drawn = false;
    std::chrono::steady_clock::time_point m_last{};
};

}  // namespace rtlab::app
