#include <rtlab/app/progress_bar.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include <unistd.h>

namespace rtlab::app {

namespace {
std::string clock(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0) return "--:--";
    const long s = std::lround(seconds);
    if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
    return fmt::format("{}:{:02}", s / 60, s % 60);
}

std::string rate(double rays_per_second) {
    if (rays_per_second >= 1e6) return fmt::format("{:.2f} Mrays/s", rays_per_second * 1e-6);
    if (rays_per_second >= 1e3) return fmt::format("{:.1f} krays/s", rays_per_second * 1e-3);
    return fmt::format("{:.0f} rays/s", rays_per_second);
}
}  // namespace

std::string format_progress(const RenderProgress& p, int bar_width) {
    const double fraction = p.tiles_total > 0 ? std::clamp(double(p.tiles_done) / p.tiles_total, 0.0, 1.0) : 0.0;
    const int filled = static_cast<int>(fraction * bar_width);
    const double per_second = p.seconds > 0.0 ? static_cast<double>(p.rays.total()) / p.seconds : 0.0;
    const double left = p.tiles_done > 0 ? p.seconds * (p.tiles_total - p.tiles_done) / p.tiles_done : -1.0;
    const int digits = static_cast<int>(std::to_string(p.tiles_total).size());
    return fmt::format("[{}{}] {:>{}}/{} tiles  {}  {} elapsed  {} left", std::string(filled, '#'),
                       std::string(bar_width - filled, '.'), p.tiles_done, digits, p.tiles_total, rate(per_second),
                       clock(p.seconds), clock(left));
}

ProgressBar::ProgressBar(std::FILE* out, bool quiet)
    : m_out(out), m_enabled(!quiet && out != nullptr && ::isatty(::fileno(out)) == 1) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(const RenderProgress& progress) {
    if (!m_enabled) return;
    const auto now = std::chrono::steady_clock::now();
    const bool last = progress.tiles_done >= progress.tiles_total;
    if (m_drawn && !last && now - m_last < std::chrono::milliseconds(100)) return;
    m_last = now;
    m_drawn = true;
    // \x1b[K clears what a longer previous line left at the end.
    fmt::print(m_out, "\r{}\x1b[K", format_progress(progress));
    std::fflush(m_out);
}

void ProgressBar::finish() {
    if (!m_drawn) return;
    std::fputc('\n', m_out);
    std::fflush(m_out);
    m_drawn = false;
}

}  // namespace rtlab::app
