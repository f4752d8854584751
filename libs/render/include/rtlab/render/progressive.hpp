#pragma once
/// \brief The progressive renderer: samples [A, B) of every pixel per pass, accumulated into per-pixel sums, with a
/// callback per finished tile and per pass, so a program can watch, stop, resume or split a render by samples.
///
/// Sample i of pixel (x, y) is a pure function of (seed, x, y, i): its camera ray takes the pixel offset and lens
/// point from pairs kPixelPair and kLensPair of SampleStream(sequence, {seed, x, y, i, 0}), and the radiance source
/// gets that stream (RadianceSource::sample_radiance, or radiance_batch for groups of coherent rays) to draw its own
/// dimensions from kFirstIntegratorPair up (rtlab/core/sample_stream.hpp documents the numbering). Every pixel adds
/// its samples in index order, so the sums, and the image, are the same bytes for any thread count, tile size and
/// split into passes: 8 samples in one pass, in 8 passes of 1, or as [0, 3) then [3, 8). Pixels may be given
/// different sample counts in a pass (adaptive sampling: rtlab/render/noise_target.hpp); the sums are added in
/// blocks of block_samples (PixelSums), so that shares of a frame rendered apart merge into the same bytes
/// (rtlab/render/sample_share.hpp).
#include <rtlab/core/image.hpp>
#include <rtlab/core/sample_stream.hpp>
#include <rtlab/render/camera.hpp>
#include <rtlab/render/radiance_source.hpp>
#include <rtlab/render/renderer.hpp>
#include <rtlab/render/sample_buffer.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace rtlab {

/// \brief How to render progressively.
struct ProgressiveSettings {
    SampleSequence sequence = SampleSequence::sobol;
    std::uint32_t first_sample = 0;  ///< the render holds samples [first_sample, first_sample + spp) of each pixel
    int spp = 16;                    ///< at least 1; first_sample + spp below 2^32
    /// Samples per pixel per pass: passes are [first + k p, first + (k + 1) p), the last one shorter; 0 renders all
    /// samples in one pass. Changes when callbacks come, never the image.
    int pass_samples = 0;
    std::uint64_t seed = 0;  ///< SampleKey::seed of every sample
    /// The block size of the sums (PixelSums): the same for every share of a frame and for its one-process render.
    std::uint32_t block_samples = kDefaultBlockSamples;
    int tile_size = 0;  ///< as RenderSettings::tile_size (0: auto_tile_size)
    int threads = 0;    ///< 0: as many as the machine has
    /// Groups of samples go to RadianceSource::radiance_batch; false: one at a time to sample_radiance() (the same
    /// image; for measurements).
    bool packets = true;
};

/// \brief A finished tile of a pass: its pixels x0 <= x < x1, y0 <= y < y1 now hold every sample below
/// `pass_end` (or all they will get when the pass was stopped). Other tiles may be being written meanwhile.
struct TileUpdate {
    int x0, y0, x1, y1;
    int pass;                    ///< 0 for the first pass of the render
    std::uint32_t pass_end;      ///< samples below this index are in the tile
    const SampleBuffer& buffer;  ///< read only the tile's pixels: others are being written
};

/// \brief A finished pass: every pixel holds samples [buffer.first_sample(), pass_end). No tile is being written.
struct PassUpdate {
    int pass;
    std::uint32_t pass_begin, pass_end;
    const SampleBuffer& buffer;
    const RenderStats& stats;  ///< totals of the render so far
};

/// \brief RenderCallbacks (progress after each finished tile of any pass, counting tiles over all passes, and the
/// stop flag, checked before every group of camera samples: at most two pixel rows of a tile at one sample index)
/// plus the progressive renderer's own. Callbacks run one at a time: `tile` and `progress` from worker threads
/// under one lock, `pass` on the calling thread between passes. Once the stop flag is seen no tile starts and no
/// pass callback comes (a tile whose last group was already traced still reports).
struct ProgressiveCallbacks : RenderCallbacks {
    std::function<void(const TileUpdate&)> tile;
    std::function<void(const PassUpdate&)> pass;
};

/// \brief A progressive render in the making: the viewer's and the sample-range share's object. It owns the
/// sums; each call to render_to() adds passes. The camera and radiance source must outlive it.
class ProgressiveRenderer {
public:
    /// Throws rtlab::Error for a non-positive image size or bad settings (spp is not read here).
    ProgressiveRenderer(const Camera& camera, const RadianceSource& radiance, const ProgressiveSettings& settings);

    /// Adds to every pixel its samples from next_sample(x, y) up to `end` (exclusive), in one pass; pixels a
    /// stopped pass left behind catch up first, so a stopped pass can simply be asked for again. Returns false
    /// when the stop flag ended the pass. `pass` is the index reported in the callbacks.
    bool render_to(std::uint32_t end, const ProgressiveCallbacks& callbacks = {}, int pass = 0);
    /// The same with an end per pixel (`ends`, row-major, width x height): pixel p gets its samples up to ends[p]
    /// (none when it holds them already). Throws rtlab::Error for another number of ends.
    bool render_to(const std::vector<std::uint32_t>& ends, const ProgressiveCallbacks& callbacks = {}, int pass = 0);

    /// Counts `passes` more passes in RenderProgress::tiles_total from now on, so that progress over several
    /// render_to calls grows steadily to 1; without it each call counts its own tiles only when it starts.
    void plan_passes(int passes);
    int tiles_per_pass() const;

    const SampleBuffer& buffer() const { return m_buffer; }
    /// Rays, time (summed over render_to calls), tiles done and total over the passes so far.
    const RenderStats& stats() const { return m_stats; }

private:
    struct Ends;
    bool render_pass(const Ends& ends, const ProgressiveCallbacks& callbacks, int pass);

    const Camera& m_camera;
    const RadianceSource& m_radiance;
    ProgressiveSettings m_settings;
    int m_tile_size;
    SampleBuffer m_buffer;
    RenderStats m_stats;
};

/// \brief What render_progressive() made.
struct ProgressiveResult {
    Image image;          ///< the mean of each pixel's samples (buffer.mean_image())
    SampleBuffer buffer;  ///< sums, sums of squares and counts: variance and half-images follow from them
    RenderStats stats;
};

/// Renders samples [settings.first_sample, settings.first_sample + settings.spp) of every pixel in passes of
/// settings.pass_samples, calling the callbacks as documented at ProgressiveCallbacks. Throws rtlab::Error for bad
/// settings; exceptions thrown by the radiance source reach the caller. When stopped, stats.cancelled is set and
/// the buffer's counts say what each pixel got.
ProgressiveResult render_progressive(const Camera& camera, const RadianceSource& radiance,
                                     const ProgressiveSettings& settings, const ProgressiveCallbacks& callbacks = {});

}  // namespace rtlab
