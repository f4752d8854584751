#include "tile_parallel.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/progressive.hpp>
#include <rtlab/render/renderer.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

namespace rtlab {

namespace {

using detail::stopped;
using detail::Tile;

/// Everything a tile needs; shared read-only by the workers.
struct TileContext {
    const Camera& camera;
    const RadianceSource& radiance;
    const RenderSettings& settings;
    const RenderCallbacks& callbacks;
    Image& image;
    std::vector<std::uint32_t>& samples;
};

/// One camera sample's ray: through `position` with the lens sample of `key`, counted.
Ray camera_ray(const TileContext& c, Vec2 position, const SampleKey& key, RayCounters& counters) {
    const Vec2 lens = c.camera.uses_lens_sample() ? sample_uniform2(key, kLensDimension) : Vec2(0.5f);
    ++counters.camera;
    return c.camera.generate_ray(position, lens);
}

/// One camera sample: the radiance along camera_ray().
RGB trace(const TileContext& c, Vec2 position, const SampleKey& key, RayCounters& counters) {
    const Ray ray = camera_ray(c, position, key, counters);
    return c.radiance.radiance(ray, key, counters);
}

/// A fixed pattern's pixel: the mean of its n samples' sum, and its sample count.
void store_pixel(const TileContext& c, int x, int y, const RGB& sum, int n) {
    c.image.at(x, y) = sum / static_cast<float>(n);
    c.samples[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.image.width()) + static_cast<std::size_t>(x)] =
        static_cast<std::uint32_t>(n);
}

/// Returns false when stopped before the tile was complete.
bool render_fixed_tile(const TileContext& c, const Tile& t, RayCounters& counters) {
    const RenderSettings& s = c.settings;
    const int n = pattern_sample_count(s.pattern, s.spp);
    for (int y = t.y0; y < t.y1; ++y) {
        for (int x = t.x0; x < t.x1; ++x) {
            if (stopped(c.callbacks)) return false;
            const SampleKey pixel{s.seed, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 0, 0};
            RGB sum;
            for (int i = 0; i < n; ++i) {
                const Vec2 offset = pattern_sample(s.pattern, s.spp, i, pixel);
                SampleKey key = pixel;
                key.sample = static_cast<std::uint32_t>(i);
                sum += trace(c, Vec2(static_cast<float>(x), static_cast<float>(y)) + offset, key, counters);
            }
            store_pixel(c, x, y, sum, n);
        }
    }
    return true;
}

/// render_fixed_tile() with the samples in groups (RenderSettings::packets): one sample index over two pixel rows
/// at a time, each pixel's sum taking its samples in the same order.
bool render_fixed_tile_groups(const TileContext& c, const Tile& t, RayCounters& counters) {
    const RenderSettings& s = c.settings;
    const int n = pattern_sample_count(s.pattern, s.spp);
    const std::size_t row = static_cast<std::size_t>(t.x1 - t.x0);
    std::vector<CameraSample> samples;
    samples.reserve(2 * row);
    std::vector<RGB> values(2 * row), sums(2 * row);
    for (int y = t.y0; y < t.y1; y += 2) {
        if (stopped(c.callbacks)) return false;
        const int y1 = std::min(y + 2, t.y1);
        std::fill(sums.begin(), sums.end(), RGB{});
        for (int i = 0; i < n; ++i) {
            samples.clear();
            for (int yy = y; yy < y1; ++yy)
                for (int x = t.x0; x < t.x1; ++x) {
                    SampleKey key{s.seed, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(yy), 0, 0};
                    const Vec2 offset = pattern_sample(s.pattern, s.spp, i, key);
                    key.sample = static_cast<std::uint32_t>(i);
                    const Vec2 position = Vec2(static_cast<float>(x), static_cast<float>(yy)) + offset;
                    samples.push_back(CameraSample{camera_ray(c, position, key, counters),
                                                   SampleStream(SampleSequence::independent, key)});
                }
            c.radiance.radiance_batch(samples, std::span<RGB>(values.data(), samples.size()), counters);
            for (std::size_t k = 0; k < samples.size(); ++k) sums[k] += values[k];
        }
        std::size_t k = 0;
        for (int yy = y; yy < y1; ++yy)
            for (int x = t.x0; x < t.x1; ++x, ++k) store_pixel(c, x, yy, sums[k], n);
    }
    return true;
}

/// The corners of one row of pixels of a tile: (R + 1) lattice rows of (tile width * R + 1) points,
/// R = 2^max_depth. The bottom lattice row becomes the next pixel row's top, so every lattice point of a
/// tile is traced at most once.
///
/// With RenderSettings::packets, for a radiance source that traces groups faster (RadianceSource::traces_batches),
/// the camera rays go to it in groups of coherent rays, as a fixed pattern's do: the pixel corners (every R-th point of
/// every R-th lattice row, which every pixel traces) of two pixel rows at a time, then the points inside a row's pixels
/// level by level, those that the recursion will ask for, before it runs. A point traced ahead is counted
/// (RenderResult::samples) by the pixel that first asks for it, as it would have been traced, so counts and image are
/// the same either way.
class AdaptiveRow {
public:
    AdaptiveRow(const TileContext& c, const Tile& t)
        : m_c(c),
          m_tile(t),
          m_res(1 << c.settings.adaptive.max_depth),
          m_cols((t.x1 - t.x0) * m_res + 1),
          m_values(static_cast<std::size_t>((m_res + 1) * m_cols)),
          m_state(m_values.size(), kNotTraced) {}

    /// Renders pixel row y of the tile; false when stopped before its end.
    bool render_row(int y, RayCounters& counters) {
        m_y = y;
        if (m_c.settings.packets && m_c.radiance.traces_batches()) {
            trace_pixel_corners(counters);
            if (!trace_refinements(counters)) return false;
        }
        for (int x = m_tile.x0; x < m_tile.x1; ++x) {
            // Per pixel: at depth 8 one pixel may trace 66,049 rays.
            if (stopped(m_c.callbacks)) return false;
            m_traced = 0;
            const int i0 = (x - m_tile.x0) * m_res;
            m_c.image.at(x, y) = square(i0, 0, m_res, counters);
            m_c.samples[static_cast<std::size_t>(y) * static_cast<std::size_t>(m_c.image.width()) +
                        static_cast<std::size_t>(x)] = m_traced;
        }
        // The bottom lattice row is the next pixel row's top.
        const std::size_t row = static_cast<std::size_t>(m_cols);
        std::copy(m_values.end() - static_cast<std::ptrdiff_t>(row), m_values.end(), m_values.begin());
        std::copy(m_state.end() - static_cast<std::ptrdiff_t>(row), m_state.end(), m_state.begin());
        std::fill(m_state.begin() + static_cast<std::ptrdiff_t>(row), m_state.end(), kNotTraced);
        return true;
    }

private:
    // A lattice point's value is not traced yet, traced and counted by a pixel, or traced ahead in a group and
    // not yet counted (kQueued: in the group being formed).
    static constexpr unsigned char kNotTraced = 0, kCounted = 1, kTracedAhead = 2, kQueued = 3;
    // The most squares trace_refinements() takes in one level, which bounds what its levels hold (3 MB of the next
    // level's squares; depth 3 makes at most 64 pixels x 16 squares a level, depth 8 reaches the bound).
    static constexpr std::size_t kMaxRefinementSquares = 1u << 16;

    std::size_t index(int i, int j) const {
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(m_cols) + static_cast<std::size_t>(i);
    }

    // The lattice point (i, j) of pixel row `y`'s lattice: its position on the image and its sample's key.
    std::pair<Vec2, SampleKey> lattice_point(int i, int j, int y) const {
        const std::uint32_t lx =
            static_cast<std::uint32_t>(m_tile.x0) * static_cast<std::uint32_t>(m_res) + static_cast<std::uint32_t>(i);
        const std::uint32_t ly =
            static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(m_res) + static_cast<std::uint32_t>(j);
        // Exact: lx and ly stay below 2^24 (checked in render()) and the division is by a power of two.
        const Vec2 position(static_cast<float>(lx) / static_cast<float>(m_res),
                            static_cast<float>(ly) / static_cast<float>(m_res));
        return {position, SampleKey{m_c.settings.seed, lx, ly, 0, 0}};
    }

    const RGB& corner(int i, int j, RayCounters& counters) {
        const std::size_t k = index(i, j);
        if (m_state[k] != kCounted) {
            if (m_state[k] == kNotTraced) {
                const auto [position, key] = lattice_point(i, j, m_y);
                m_values[k] = trace(m_c, position, key, counters);
            }
            m_state[k] = kCounted;
            ++m_traced;
        }
        return m_values[k];
    }

    // The lattice points inside the row's pixels that square() will ask for, traced ahead level by level: at each
    // level the squares whose corners differ (the same decision square() takes on the same values) hand the midpoints
    // of their sides and their centre to a group. A group holds at most as many points as one pixel may trace, so a
    // stop (looked at after each group) still ends the render within about one pixel's rays per thread; past
    // kMaxRefinementSquares squares in a level, square() traces the rest one at a time.
    bool trace_refinements(RayCounters& counters) {
        const std::size_t group_limit = static_cast<std::size_t>(m_res + 1) * static_cast<std::size_t>(m_res + 1);
        m_squares.clear();
        for (int p = 0; p < m_tile.x1 - m_tile.x0; ++p) m_squares.push_back({p * m_res, 0, m_res});
        m_group.clear();
        m_targets.clear();
        while (!m_squares.empty() && m_squares.size() <= kMaxRefinementSquares) {
            m_next.clear();
            for (const Square& q : m_squares) {
                if (q.size == 1 || !differ(ahead(q.i, q.j), ahead(q.i + q.size, q.j), ahead(q.i, q.j + q.size),
                                           ahead(q.i + q.size, q.j + q.size)))
                    continue;
                const int h = q.size / 2;
                for (const auto& [di, dj] : {std::pair{h, 0}, {0, h}, {h, h}, {q.size, h}, {h, q.size}}) {
                    const std::size_t k = index(q.i + di, q.j + dj);
                    if (m_state[k] != kNotTraced) continue;
                    m_state[k] = kQueued;
                    queue(lattice_point(q.i + di, q.j + dj, m_y), Target{false, k}, counters);
                }
                for (const auto& [di, dj] : {std::pair{0, 0}, {h, 0}, {0, h}, {h, h}})
                    m_next.push_back({q.i + di, q.j + dj, h});
                if (m_group.size() + 5 > group_limit && !flush_group(counters)) return false;
            }
            // The next level's squares read this level's points.
            if (!flush_group(counters)) return false;
            std::swap(m_squares, m_next);
        }
        return true;
    }

    // Traces the group formed so far (trace_group); false when the render has been stopped.
    bool flush_group(RayCounters& counters) {
        trace_group(counters);
        m_group.clear();
        m_targets.clear();
        return !stopped(m_c.callbacks);
    }

    // Adds a lattice point's camera sample (with the independent stream of its key, as a fixed pattern's) to the
    // group, its value to go to `target`.
    struct Target;
    void queue(const std::pair<Vec2, SampleKey>& point, const Target& target, RayCounters& counters) {
        const auto& [position, key] = point;
        m_group.push_back(
            CameraSample{camera_ray(m_c, position, key, counters), SampleStream(SampleSequence::independent, key)});
        m_targets.push_back(target);
    }

    // A lattice point's value that trace_refinements() knows: one traced before it looks at the point's square.
    const RGB& ahead(int i, int j) const { return m_values[index(i, j)]; }

    // Traces m_group with radiance_batch() and stores each value where its m_targets entry says.
    void trace_group(RayCounters& counters) {
        if (m_group.empty()) return;
        m_group_values.resize(m_group.size());
        m_c.radiance.radiance_batch(m_group, m_group_values, counters);
        for (std::size_t g = 0; g < m_group.size(); ++g) {
            const Target& target = m_targets[g];
            if (target.ahead) {
                m_ahead[target.index] = m_group_values[g];
            } else {
                m_values[target.index] = m_group_values[g];
                m_state[target.index] = kTracedAhead;
            }
        }
    }

    // The pixel corners of row m_y not traced yet (its top ones only in a tile's first row) and, when the tile has
    // one, those at the bottom of the next row, as one group (kept in m_ahead for the next row). A group is two rows of
    // pixel corners (three in a tile's first row): radiance_batch() takes them column by column, so its packets hold
    // 4 x 2 corners.
    void trace_pixel_corners(RayCounters& counters) {
        const int pixels = m_tile.x1 - m_tile.x0;
        const int bottom = m_res;  // the lattice row of the pixel row's bottom corners
        if (m_ahead_row == m_y) {
            for (int p = 0; p <= pixels; ++p) {
                const std::size_t k = index(p * m_res, bottom);
                m_values[k] = m_ahead[static_cast<std::size_t>(p)];
                m_state[k] = kTracedAhead;
            }
            return;
        }
        m_group.clear();
        m_targets.clear();
        const bool next_row = m_y + 1 < m_tile.y1;
        for (const int j : {0, bottom, 2 * bottom}) {
            if (j == 2 * bottom && !next_row) break;
            for (int p = 0; p <= pixels; ++p) {
                const int i = p * m_res;
                const bool ahead = j == 2 * bottom;
                if (!ahead && m_state[index(i, j)] != kNotTraced) continue;
                queue(ahead ? lattice_point(i, bottom, m_y + 1) : lattice_point(i, j, m_y),
                      ahead ? Target{true, static_cast<std::size_t>(p)} : Target{false, index(i, j)}, counters);
            }
        }
        m_ahead.resize(static_cast<std::size_t>(pixels + 1));
        trace_group(counters);
        m_ahead_row = next_row ? m_y + 1 : -1;
    }

    /// The value of the square with top-left lattice corner (i, j) and side `size` lattice steps. The
    /// side halves at every split and a side of 1 is never split: this is what bounds the recursion.
    RGB square(int i, int j, int size, RayCounters& counters) {
        const RGB c00 = corner(i, j, counters);
        const RGB c10 = corner(i + size, j, counters);
        const RGB c01 = corner(i, j + size, counters);
        const RGB c11 = corner(i + size, j + size, counters);
        if (size > 1 && differ(c00, c10, c01, c11)) {
            const int h = size / 2;
            const RGB a = square(i, j, h, counters);
            const RGB b = square(i + h, j, h, counters);
            const RGB c = square(i, j + h, h, counters);
            const RGB d = square(i + h, j + h, h, counters);
            return (a + b + c + d) * 0.25f;
        }
        return (c00 + c10 + c01 + c11) * 0.25f;
    }

    /// display_difference() of every pair against the threshold, each corner clamped once rather than once
    /// per pair. A NaN component stays NaN through the clamp and its difference, which then counts 1 as there.
    bool differ(const RGB& a, const RGB& b, const RGB& c, const RGB& d) const {
        const float th = m_c.settings.adaptive.threshold;
        const RGB ca = clamped(a), cb = clamped(b), cc = clamped(c), cd = clamped(d);
        return distance(ca, cb) > th || distance(ca, cc) > th || distance(ca, cd) > th || distance(cb, cc) > th ||
               distance(cb, cd) > th || distance(cc, cd) > th;
    }

    static RGB clamped(const RGB& v) {
        return {std::clamp(v.r, 0.0f, 1.0f), std::clamp(v.g, 0.0f, 1.0f), std::clamp(v.b, 0.0f, 1.0f)};
    }

    static float component_distance(float a, float b) {
        const float d = std::abs(a - b);
        return std::isnan(d) ? 1.0f : d;
    }

    static float distance(const RGB& a, const RGB& b) {
        return component_distance(a.r, b.r) + component_distance(a.g, b.g) + component_distance(a.b, b.b);
    }

    const TileContext& m_c;
    Tile m_tile;
    int m_res;
    int m_cols;
    int m_y = 0;
    std::uint32_t m_traced = 0;
    std::vector<RGB> m_values;
    std::vector<unsigned char> m_state;
    // The group being formed (trace_pixel_corners, trace_refinements), where each of its values goes, and the next
    // row's bottom corners.
    struct Target {
        bool ahead;         // into m_ahead rather than m_values
        std::size_t index;  // in m_ahead or m_values
    };
    struct Square {
        int i, j, size;  // as square() takes them
    };
    std::vector<Square> m_squares, m_next;  // trace_refinements()'s squares of this level and of the next
    std::vector<CameraSample> m_group;
    std::vector<RGB> m_group_values;
    std::vector<Target> m_targets;
    std::vector<RGB> m_ahead;
    int m_ahead_row = -1;  // the pixel row whose bottom corners m_ahead holds, -1 for none
};

bool render_adaptive_tile(const TileContext& c, const Tile& t, RayCounters& counters) {
    AdaptiveRow row(c, t);
    for (int y = t.y0; y < t.y1; ++y)
        if (!row.render_row(y, counters)) return false;
    return true;
}

void check_settings(const Camera& camera, const RenderSettings& s) {
    detail::check_tile_settings("render", camera, s.tile_size, s.threads);
    if (s.pattern != PixelPattern::adaptive) {
        pattern_sample_count(s.pattern, s.spp);
        return;
    }
    const AdaptiveSettings& a = s.adaptive;
    if (a.max_depth < 0 || a.max_depth > kMaxAdaptiveDepth)
        throw Error("render: adaptive depth must lie in [0, " + std::to_string(kMaxAdaptiveDepth) + "], got " +
                    std::to_string(a.max_depth));
    if (!(a.threshold >= 0.0f))
        throw Error("render: adaptive threshold must be a number >= 0, got " + std::to_string(a.threshold));
    // Lattice positions must be exact floats and fit SampleKey's 32-bit coordinates.
    const long long limit = 1LL << 24;
    if ((static_cast<long long>(camera.width()) << a.max_depth) >= limit ||
        (static_cast<long long>(camera.height()) << a.max_depth) >= limit)
        throw Error("render: image too large for adaptive depth " + std::to_string(a.max_depth) +
                    " (width and height times 2^depth must stay below 2^24)");
}

/// The sobol pattern is progressive: its samples go through render_progressive in one pass.
RenderResult render_sobol(const Camera& camera, const RadianceSource& radiance, const RenderSettings& settings,
                          const RenderCallbacks& callbacks) {
    ProgressiveSettings p;
    p.sequence = SampleSequence::sobol;
    p.spp = settings.spp;
    p.seed = settings.seed;
    p.tile_size = settings.tile_size;
    p.threads = settings.threads;
    p.packets = settings.packets;
    ProgressiveCallbacks cb;
    cb.progress = callbacks.progress;
    cb.stop = callbacks.stop;
    cb.deadline = callbacks.deadline;
    ProgressiveResult r = render_progressive(camera, radiance, p, cb);
    RenderResult result;
    result.image = std::move(r.image);
    result.samples = r.buffer.counts();
    result.stats = r.stats;
    result.buffer = std::make_shared<const SampleBuffer>(std::move(r.buffer));
    return result;
}

}  // namespace

int auto_tile_size(int width, int height) {
    const long long pixels = static_cast<long long>(width) * height;
    for (const int edge : {64, 32}) {
        if (pixels >= 128LL * edge * edge) return edge;
    }
    return 16;
}

RenderResult render(const Camera& camera, const RadianceSource& radiance, const RenderSettings& settings,
                    const RenderCallbacks& callbacks) {
    check_settings(camera, settings);
    if (settings.pattern == PixelPattern::sobol) return render_sobol(camera, radiance, settings, callbacks);
    const auto start = std::chrono::steady_clock::now();
    const int w = camera.width(), h = camera.height();
    const int ts = settings.tile_size > 0 ? settings.tile_size : auto_tile_size(w, h);
    const detail::TileGrid grid(w, h, ts);
    const int tiles_total = grid.count();

    RenderResult result;
    result.image = Image(w, h);
    result.samples.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
    result.stats.tiles_total = tiles_total;
    const TileContext context{camera, radiance, settings, callbacks, result.image, result.samples};

    std::mutex progress_mutex;  // guards the totals below and serialises the progress callback
    RayCounters totals;
    int tiles_done = 0;
    auto seconds_since_start = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };

    auto render_tile = [&](int index) {
        if (stopped(callbacks)) return;
        const Tile tile = grid.tile(index);
        RayCounters counters;
        const bool complete = settings.pattern == PixelPattern::adaptive ? render_adaptive_tile(context, tile, counters)
                              : settings.packets ? render_fixed_tile_groups(context, tile, counters)
                                                 : render_fixed_tile(context, tile, counters);
        std::lock_guard lock(progress_mutex);
        totals += counters;
        if (!complete) return;
        ++tiles_done;
        if (callbacks.progress)
            callbacks.progress(RenderProgress{tiles_done, tiles_total, totals, seconds_since_start()});
    };
    detail::for_each_tile(settings.threads, tiles_total, render_tile);

    result.stats.rays = totals;
    result.stats.tiles_done = tiles_done;
    result.stats.cancelled = tiles_done < tiles_total;
    result.stats.seconds = seconds_since_start();
    return result;
}

}  // namespace rtlab
