#pragma once
/// \brief Per-pixel sample sums: what a progressive render accumulates, and what a noise estimate, a viewer and a
/// merge of sample ranges read.
#include <rtlab/core/color.hpp>
#include <rtlab/core/image.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace rtlab {

/// \brief The sums of one pixel's samples, in double. Split by the parity of the sample index, so that the two
/// interleaved half-images (even and odd samples, two independent estimates of the same pixel) come out of the
/// same sums as the whole image, as a relative-error estimate from half-buffers needs.
struct PixelSums {
    std::array<std::array<double, 3>, 2> sum{};  ///< [parity][channel]: sums of the even and of the odd samples
    std::array<double, 3> sum_squares{};         ///< per channel, over all samples
    std::array<std::uint32_t, 2> count{};        ///< even and odd samples added

    std::uint32_t total_count() const { return count[0] + count[1]; }
};

/// \brief A width x height grid of PixelSums holding samples [first_sample(), first_sample() + count) of each
/// pixel. Samples are added one at a time; adding a pixel's samples in the same order gives the same bytes.
class SampleBuffer {
public:
    SampleBuffer() = default;
    /// Throws rtlab::Error for a non-positive size.
    SampleBuffer(int width, int height, std::uint32_t first_sample = 0);

    int width() const { return m_width; }
    int height() const { return m_height; }
    /// The sample index the buffer starts at: pixel p holds samples [first_sample, first_sample + count(p)).
    std::uint32_t first_sample() const { return m_first_sample; }

    /// Adds sample `index` of pixel (x, y): the parity of `index` picks the half. Callers add a pixel's samples in
    /// index order, each once; next_sample() is the one that comes next.
    void add(int x, int y, std::uint32_t index, const RGB& value) {
        PixelSums& p = m_pixels[offset(x, y)];
        const std::size_t half = index & 1u;
        for (int c = 0; c < 3; ++c) {
            const double v = static_cast<double>(value[c]);
            p.sum[half][static_cast<std::size_t>(c)] += v;
            p.sum_squares[static_cast<std::size_t>(c)] += v * v;
        }
        ++p.count[half];
    }

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
    /// The variance of the pixel's mean: sample_variance / n (0 below 2 samples).
    RGB mean_variance(int x, int y) const;

    /// Images of the above, row-major like Image.
    Image mean_image() const;
    Image half_mean_image(int parity) const;
    Image mean_variance_image() const;
    /// Samples per pixel, row-major (RenderResult::samples).
    std::vector<std::uint32_t> counts() const;
    /// The smallest count over all pixels: every pixel holds at least this many samples.
    std::uint32_t min_count() const;

    /// Adds `other`'s sums and counts pixel by pixel (a share of samples rendered elsewhere). Throws rtlab::Error
    /// for another size. The result holds the same samples as one render but is not its bytes: the sums are
    /// associated differently (a byte-identical merge needs the shares' sums kept per block of samples).
    void merge(const SampleBuffer& other);

    friend bool operator==(const SampleBuffer& a, const SampleBuffer& b);

private:
    std::size_t offset(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(m_width) + static_cast<std::size_t>(x);
    }

    int m_width = 0, m_height = 0;
    std::uint32_t m_first_sample = 0;
    std::vector<PixelSums> m_pixels;
};

}  // namespace rtlab
