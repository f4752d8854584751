#pragma once
/// \brief The parallel tile renderer: camera + radiance source -> HDR image, with progress and cancel.
#include <rtlab/core/image.hpp>
#include <rtlab/render/camera.hpp>
#include <rtlab/render/pixel_sampler.hpp>
#include <rtlab/render/radiance_source.hpp>
#include <rtlab/render/sample_buffer.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace rtlab {

/// \brief How to render. The image does not depend on `threads` or on the tile size.
struct RenderSettings {
    PixelPattern pattern = PixelPattern::none;
    int spp = 1;                ///< samples per pixel for grid, random, jittered and sobol
    AdaptiveSettings adaptive;  ///< for PixelPattern::adaptive
    std::uint64_t seed = 0;     ///< SampleKey::seed of every sample
    /// Tiles are tile_size x tile_size pixels (smaller at the right and bottom); 0 picks it from the image size
    /// alone (auto_tile_size), never from the thread count, so that ray counts do not depend on threads.
    int tile_size = 0;
    int threads = 0;  ///< 0: as many as the machine has (TBB's default)
    /// The fixed patterns (none, grid, random, jittered) and sobol hand the radiance source groups of coherent
    /// samples, one sample index over up to two pixel rows of a tile (RadianceSource::radiance_batch; a fixed
    /// pattern's samples with the independent stream of their key), and adaptive sampling its points (ahead of its
    /// recursion, for a source whose traces_batches() is true); false: one sample at a time (radiance(), or
    /// sample_radiance() for sobol), for measurements. The image is the same either way.
    bool packets = true;
};

/// The tile edge for tile_size 0: the largest of 64, 32 and 16 pixels that still cuts the image into at least
/// 128 tiles (16 below that). Adaptive sampling traces the lattice points on a tile's border once per tile, so
/// larger tiles trace fewer of them twice (16-pixel tiles traced 13% more pixel corners than a 1280x960 image
/// has, 64-pixel ones 3%), while 128 tiles still keep every core busy to the end.
int auto_tile_size(int width, int height);

/// \brief Where a render is: passed to RenderCallbacks::progress after every finished tile.
struct RenderProgress {
    int tiles_done = 0;
    int tiles_total = 0;
    RayCounters rays;      ///< rays of the finished tiles
    double seconds = 0.0;  ///< since the render started
};

/// \brief What a render did.
struct RenderStats {
    RayCounters rays;
    double seconds = 0.0;
    int tiles_done = 0;
    int tiles_total = 0;
    bool cancelled = false;  ///< the stop flag was seen: some tiles may be missing
    double rays_per_second() const { return seconds > 0.0 ? static_cast<double>(rays.total()) / seconds : 0.0; }
};

/// \brief How the renderer talks back. The library writes nothing to stdout or stderr itself.
struct RenderCallbacks {
    /// Called after each finished tile, from a worker thread, never by two threads at once.
    std::function<void(const RenderProgress&)> progress;
    /// When set and true, workers stop before their next pixel and render() returns what is done.
    const std::atomic<bool>* stop = nullptr;
    /// Workers stop likewise once the steady clock passes this time (a render with a time budget); the clock is
    /// read only when it is set.
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

/// \brief The rendered image and what it cost.
struct RenderResult {
    Image image;                         ///< linear radiance; pixels never reached are black
    std::vector<std::uint32_t> samples;  ///< camera rays each pixel traced, row-major; 0: not rendered
    RenderStats stats;
    /// The per-pixel sums of a progressive pattern (sobol): variance and half-images; null for the others.
    std::shared_ptr<const SampleBuffer> buffer;
};

/// Renders camera.width() x camera.height() pixels in parallel tiles; the sobol pattern goes to
/// render_progressive() in one pass (its radiance source sees SampleStreams through sample_radiance or
/// radiance_batch). Throws rtlab::Error for bad
/// settings (spp, tile size, thread count, adaptive depth or threshold); exceptions thrown by the
/// radiance source reach the caller. With the adaptive pattern a corner shared by neighbouring pixels is
/// traced once per tile and counted by the pixel that needed it first.
RenderResult render(const Camera& camera, const RadianceSource& radiance, const RenderSettings& settings,
                    const RenderCallbacks& callbacks = {});

}  // namespace rtlab
