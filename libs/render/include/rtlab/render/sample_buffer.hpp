#pragma once
/// \brief Per-pixel sample sums: what a progressive render accumulates, and what a noise estimate, a viewer and a
/// merge of sample ranges read.
#include <rtlab/core/color.hpp>
#include <rtlab/core/image.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace rtlab {

/// The samples a pixel's sums gather before they are added to its total, by default: see PixelSums.
inline constexpr std::uint32_t kDefaultBlockSamples = 64;

/// \brief The sums of a run of one pixel's samples, in double. Split by the parity of the sample index, so that
/// the two interleaved half-images (even and odd samples) come out of the same sums as the whole image, as a
/// relative-error estimate from half-buffers needs (independent halves need SampleSequence::sobol_halves).
struct SampleSums {
    std::array<std::array<double, 3>, 2> sum{};  ///< [parity][channel]: sums of the even and of the odd samples
    std::array<double, 3> sum_squares{};         ///< per channel, over all samples
    std::array<std::uint32_t, 2> count{};        ///< even and odd samples added

    std::uint32_t total_count() const { return count[0] + count[1]; }

    void add(std::uint32_t index, const RGB& value) {
        const std::size_t half = index & 1u;
        for (std::size_t c = 0; c < 3; ++c) {
            const double v = static_cast<double>(value[static_cast<int>(c)]);
            sum[half][c] += v;
            sum_squares[c] += v * v;
        }
        ++count[half];
    }
    SampleSums& operator+=(const SampleSums& o) {
        for (std::size_t c = 0; c < 3; ++c) {
            sum[0][c] += o.sum[0][c];
            sum[1][c] += o.sum[1][c];
            sum_squares[c] += o.sum_squares[c];
        }
        count[0] += o.count[0];
        count[1] += o.count[1];
        return *this;
    }
};

/// \brief One pixel's sums, accumulated in fixed blocks of sample indices [kB, (k + 1)B) (B the buffer's block
/// size): each sample is added to the sums of the block it falls in (`block`, started from zero), and when the
/// first sample of the next block comes those sums are added to `done`, block after block in sample order.
///
/// Why blocks: floating-point addition is not associative, so sums of a share of samples [A, B) rendered
/// elsewhere, added to the sums of [0, A), would not be the bytes one render of [0, B) makes. With blocks aligned
/// to the shares' boundaries each block's sums are the same bytes wherever it was rendered, and adding the
/// blocks in order (SampleBuffer::add_block) repeats exactly the additions of one render.
struct PixelSums {
    SampleSums done;   ///< the blocks before the current one, added in order
    SampleSums block;  ///< the block being filled

    std::uint32_t total_count() const { return done.total_count() + block.total_count(); }
    std::uint32_t count(int parity) const {
        const std::size_t h = static_cast<std::size_t>(parity & 1);
        return done.count[h] + block.count[h];
    }
    /// The sum of the pixel's samples of one parity, channel c.
    double sum(int parity, int c) const {
        const std::size_t h = static_cast<std::size_t>(parity & 1), i = static_cast<std::size_t>(c);
        return done.sum[h][i] + block.sum[h][i];
    }
    double sum_squares(int c) const {
        const std::size_t i = static_cast<std::size_t>(c);
        return done.sum_squares[i] + block.sum_squares[i];
    }
};

/// \brief A width x height grid of PixelSums holding samples [first_sample(), first_sample() + count) of each
/// pixel. Samples are added one at a time; adding a pixel's samples in the same order gives the same bytes.
class SampleBuffer {
public:
    SampleBuffer() = default;
    /// Throws rtlab::Error for a non-positive size or block size.
    SampleBuffer(int width, int height, std::uint32_t first_sample = 0,
                 std::uint32_t block_samples = kDefaultBlockSamples);

    int width() const { return m_width; }
    int height() const { return m_height; }
    /// The sample index the buffer starts at: pixel p holds samples [first_sample, first_sample + count(p)).
    std::uint32_t first_sample() const { return m_first_sample; }
    /// The block size B of the accumulation (PixelSums).
    std::uint32_t block_samples() const { return m_block_samples; }

    /// Adds sample `index` of pixel (x, y): the parity of `index` picks the half. Callers add a pixel's samples in
    /// index order, each once; next_sample() is the one that comes next.
    void add(int x, int y, std::uint32_t index, const RGB& value) {
        PixelSums& p = m_pixels[offset(x, y)];
        if (index % m_block_samples == 0 && p.block.total_count() > 0) {
            p.done += p.block;
            p.block = SampleSums{};
        }
        p.block.add(index, value);
    }

    /// Adds the sums of a whole block of pixel (x, y)'s samples, made elsewhere by add() from zero (a share's
    /// block): the same bytes as adding its samples one by one. The block must start at next_sample(x, y), on a
    /// block boundary (or at first_sample()); throws rtlab::Error otherwise.
    void add_block(int x, int y, std::uint32_t block_first, const SampleSums& sums);

    const PixelSums& at(int x, int y) const { return m_pixels[offset(x, y)]; }
    std::uint32_t count(int x, int y) const { return at(x, y).total_count(); }
    /// The index of the next sample pixel (x, y) needs: first_sample() + count(x, y).
    std::uint32_t next_sample(int x, int y) const { return m_first_sample + count(x, y); }

    /// The mean of the pixel's samples; black without samples.
    RGB mean(int x, int y) const;
    /// The mean of the pixel's even (parity 0) or odd (parity 1) samples; black without any.
    RGB half_mean(int x, int y, int parity) const;
    /// The unbiased variance of one sample, (sum of squares - sum^2 / n) / (n - 1) per channel, clamped at 0
    /// against rounding; 0 below 2 samples (a caller deciding where to sample checks count() first).
    RGB sample_variance(int x, int y) const;
    /// The variance of the pixel's mean: sample_variance / n (0 below 2 samples). It takes the samples as
    /// independent, so for low-discrepancy samples it is an upper estimate.
    RGB mean_variance(int x, int y) const;

    /// Images of the above, row-major like Image.
    Image mean_image() const;
    Image half_mean_image(int parity) const;
    Image mean_variance_image() const;
    /// Samples per pixel, row-major (RenderResult::samples).
    std::vector<std::uint32_t> counts() const;
    /// The smallest count over all pixels: every pixel holds at least this many samples.
    std::uint32_t min_count() const;
    /// All samples of all pixels.
    std::uint64_t total_samples() const;

    /// Adds `other`'s sums and counts pixel by pixel (samples rendered elsewhere). Throws rtlab::Error for another
    /// size. The result holds the same samples as one render but is not its bytes: the sums are associated
    /// differently (a byte-identical merge adds the blocks one by one: add_block, rtlab/render/sample_share.hpp).
    void merge(const SampleBuffer& other);

    friend bool operator==(const SampleBuffer& a, const SampleBuffer& b);

private:
    std::size_t offset(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(m_width) + static_cast<std::size_t>(x);
    }

    int m_width = 0, m_height = 0;
    std::uint32_t m_first_sample = 0;
    std::uint32_t m_block_samples = kDefaultBlockSamples;
    std::vector<PixelSums> m_pixels;
};

}  // namespace rtlab
