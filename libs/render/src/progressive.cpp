#include "tile_parallel.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/progressive.hpp>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <string>
#include <vector>

namespace rtlab {

/// Where each pixel's samples end in a pass: one index for all, or one per pixel (row-major).
struct ProgressiveRenderer::Ends {
    std::uint32_t all = 0;
    const std::uint32_t* per_pixel = nullptr;
    int width = 0;
    std::uint32_t max = 0;

    std::uint32_t at(int x, int y) const {
        return per_pixel ? per_pixel[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                     static_cast<std::size_t>(x)]
                         : all;
    }
};

namespace {

using detail::stopped;
using detail::Tile;

void check_settings(const Camera& camera, const ProgressiveSettings& s) {
    detail::check_tile_settings("progressive render", camera, s.tile_size, s.threads);
    if (s.pass_samples < 0)
        throw Error("progressive render: samples per pass must be >= 0 (0: all in one pass), got " +
                    std::to_string(s.pass_samples));
    if (s.block_samples < 1) throw Error("progressive render: the block size must be at least 1 sample");
}

/// The samples a tile adds in one pass: sample-major (index outer), so that each group handed to the radiance
/// source is one sample index over up to two neighbouring pixel rows: coherent camera rays for packets.
class TilePass {
public:
    TilePass(const Camera& camera, const RadianceSource& radiance, const ProgressiveSettings& settings,
             SampleBuffer& buffer)
        : m_camera(camera), m_radiance(radiance), m_settings(settings), m_buffer(buffer) {}

    /// False when stopped before every pixel of the tile reached its end.
    template <class Ends>
    bool render(const Tile& t, const Ends& ends, const RenderCallbacks& callbacks, RayCounters& counters) {
        std::uint32_t begin = 0xffffffffu, end = 0;
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x) {
                const std::uint32_t e = ends.at(x, y), next = m_buffer.next_sample(x, y);
                if (next >= e) continue;
                begin = std::min(begin, next);
                end = std::max(end, e);
            }
        const std::size_t group = 2 * static_cast<std::size_t>(t.x1 - t.x0);
        m_samples.reserve(group);
        m_pixels.reserve(group);
        m_values.resize(group);
        for (std::uint32_t i = begin; i < end; ++i) {
            for (int y = t.y0; y < t.y1; y += 2) {
                if (stopped(callbacks)) return false;
                m_samples.clear();
                m_pixels.clear();
                for (int yy = y; yy < std::min(y + 2, t.y1); ++yy)
                    for (int x = t.x0; x < t.x1; ++x)
                        // Only the sample a pixel needs next: each pixel's sums take its samples in order.
                        if (m_buffer.next_sample(x, yy) == i && i < ends.at(x, yy))
                            add_camera_sample(x, yy, i, counters);
                if (m_samples.empty()) continue;
                if (m_settings.packets)
                    m_radiance.radiance_batch(m_samples, std::span<RGB>(m_values.data(), m_samples.size()), counters);
                else
                    for (std::size_t k = 0; k < m_samples.size(); ++k)
                        m_values[k] = m_radiance.sample_radiance(m_samples[k], counters);
                for (std::size_t k = 0; k < m_samples.size(); ++k)
                    m_buffer.add(m_pixels[k].first, m_pixels[k].second, i, m_values[k]);
            }
        }
        return true;
    }

private:
    void add_camera_sample(int x, int y, std::uint32_t index, RayCounters& counters) {
        const SampleStream stream(m_settings.sequence, SampleKey{m_settings.seed, static_cast<std::uint32_t>(x),
                                                                 static_cast<std::uint32_t>(y), index, 0});
        const Vec2 offset = stream.get2d(kPixelPair);
        const Vec2 lens = m_camera.uses_lens_sample() ? stream.get2d(kLensPair) : Vec2(0.5f);
        const Vec2 position = Vec2(static_cast<float>(x), static_cast<float>(y)) + offset;
        m_samples.push_back(CameraSample{m_camera.generate_ray(position, lens), stream});
        m_pixels.emplace_back(x, y);
        ++counters.camera;
    }

    const Camera& m_camera;
    const RadianceSource& m_radiance;
    const ProgressiveSettings& m_settings;
    SampleBuffer& m_buffer;
    std::vector<CameraSample> m_samples;
    std::vector<std::pair<int, int>> m_pixels;
    std::vector<RGB> m_values;
};

}  // namespace

ProgressiveRenderer::ProgressiveRenderer(const Camera& camera, const RadianceSource& radiance,
                                         const ProgressiveSettings& settings)
    : m_camera(camera), m_radiance(radiance), m_settings(settings) {
    check_settings(camera, settings);
    m_tile_size = settings.tile_size > 0 ? settings.tile_size : auto_tile_size(camera.width(), camera.height());
    m_buffer = SampleBuffer(camera.width(), camera.height(), settings.first_sample, settings.block_samples);
}

int ProgressiveRenderer::tiles_per_pass() const {
    return detail::TileGrid(m_camera.width(), m_camera.height(), m_tile_size).count();
}

void ProgressiveRenderer::plan_passes(int passes) {
    m_stats.tiles_total = std::max(m_stats.tiles_total, m_stats.tiles_done + passes * tiles_per_pass());
}

bool ProgressiveRenderer::render_to(std::uint32_t end, const ProgressiveCallbacks& callbacks, int pass) {
    Ends ends;
    ends.all = end;
    ends.max = end;
    return render_pass(ends, callbacks, pass);
}

bool ProgressiveRenderer::render_to(const std::vector<std::uint32_t>& end, const ProgressiveCallbacks& callbacks,
                                    int pass) {
    const std::size_t pixels = static_cast<std::size_t>(m_camera.width()) * static_cast<std::size_t>(m_camera.height());
    if (end.size() != pixels)
        throw Error("progressive render: " + std::to_string(end.size()) + " sample ends for " + std::to_string(pixels) +
                    " pixels");
    Ends ends;
    ends.per_pixel = end.data();
    ends.width = m_camera.width();
    for (const std::uint32_t e : end) ends.max = std::max(ends.max, e);
    return render_pass(ends, callbacks, pass);
}

bool ProgressiveRenderer::render_pass(const Ends& ends, const ProgressiveCallbacks& callbacks, int pass) {
    const std::uint32_t end = ends.max;
    const auto start = std::chrono::steady_clock::now();
    const detail::TileGrid grid(m_camera.width(), m_camera.height(), m_tile_size);
    m_stats.tiles_total = std::max(m_stats.tiles_total, m_stats.tiles_done + grid.count());

    std::mutex mutex;  // guards the totals below and serialises the tile and progress callbacks
    RayCounters totals;
    int tiles_done = 0;
    const double seconds_before = m_stats.seconds;
    auto seconds_now = [&] {
        return seconds_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };

    auto render_tile = [&](int index) {
        if (stopped(callbacks)) return;
        const Tile tile = grid.tile(index);
        RayCounters counters;
        TilePass tile_pass(m_camera, m_radiance, m_settings, m_buffer);
        const bool complete = tile_pass.render(tile, ends, callbacks, counters);
        std::lock_guard lock(mutex);
        totals += counters;
        if (!complete) return;
        ++tiles_done;
        if (callbacks.tile) callbacks.tile(TileUpdate{tile.x0, tile.y0, tile.x1, tile.y1, pass, end, m_buffer});
        if (callbacks.progress) {
            RayCounters rays = m_stats.rays;
            rays += totals;
            callbacks.progress(
                RenderProgress{m_stats.tiles_done + tiles_done, m_stats.tiles_total, rays, seconds_now()});
        }
    };
    detail::for_each_tile(m_settings.threads, grid.count(), render_tile);

    m_stats.rays += totals;
    m_stats.tiles_done += tiles_done;
    m_stats.cancelled = tiles_done < grid.count();
    m_stats.seconds = seconds_now();
    return !m_stats.cancelled;
}

ProgressiveResult render_progressive(const Camera& camera, const RadianceSource& radiance,
                                     const ProgressiveSettings& settings, const ProgressiveCallbacks& callbacks) {
    if (settings.spp < 1 ||
        static_cast<std::uint64_t>(settings.first_sample) + static_cast<std::uint64_t>(settings.spp) > 0xffffffffULL)
        throw Error("progressive render: samples per pixel must be >= 1 and first sample + spp below 2^32, got " +
                    std::to_string(settings.first_sample) + " + " + std::to_string(settings.spp));
    ProgressiveRenderer renderer(camera, radiance, settings);
    const std::uint64_t first = settings.first_sample;
    const std::uint64_t last = first + static_cast<std::uint64_t>(settings.spp);
    const std::uint64_t step = settings.pass_samples > 0 ? static_cast<std::uint64_t>(settings.pass_samples) : last;
    // Every pass's tiles count in the progress from the start, so its fraction grows steadily to 1.
    renderer.plan_passes(static_cast<int>((last - first + step - 1) / step));
    int pass = 0;
    for (std::uint64_t begin = first; begin < last; begin += step, ++pass) {
        const std::uint64_t end = std::min(last, begin + step);
        if (!renderer.render_to(static_cast<std::uint32_t>(end), callbacks, pass)) break;
        if (callbacks.pass)
            callbacks.pass(PassUpdate{pass, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end),
                                      renderer.buffer(), renderer.stats()});
    }
    ProgressiveResult result{renderer.buffer().mean_image(), renderer.buffer(), renderer.stats()};
    return result;
}

}  // namespace rtlab
