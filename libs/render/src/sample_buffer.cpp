#include <rtlab/core/error.hpp>
#include <rtlab/render/sample_buffer.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

namespace rtlab {

namespace {

// operator== compares bytes: no padding may hide between the sums.
static_assert(sizeof(SampleSums) == 9 * sizeof(double) + 2 * sizeof(std::uint32_t));
static_assert(sizeof(PixelSums) == 2 * sizeof(SampleSums));

RGB to_rgb(const std::array<double, 3>& v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

template <class F>
Image image_of(const SampleBuffer& b, F&& pixel) {
    Image out(b.width(), b.height());
    for (int y = 0; y < b.height(); ++y)
        for (int x = 0; x < b.width(); ++x) out.at(x, y) = pixel(x, y);
    return out;
}

}  // namespace

SampleBuffer::SampleBuffer(int width, int height, std::uint32_t first_sample, std::uint32_t block_samples)
    : m_width(width), m_height(height), m_first_sample(first_sample), m_block_samples(block_samples) {
    if (width <= 0 || height <= 0)
        throw Error("sample buffer: size must be positive, got " + std::to_string(width) + "x" +
                    std::to_string(height));
    if (block_samples == 0) throw Error("sample buffer: the block size must be at least 1 sample");
    m_pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
}

void SampleBuffer::add_block(int x, int y, std::uint32_t block_first, const SampleSums& sums) {
    PixelSums& p = m_pixels[offset(x, y)];
    const std::uint32_t next = m_first_sample + p.total_count();
    const std::uint64_t n = sums.total_count();
    const std::uint64_t block_end = (static_cast<std::uint64_t>(block_first) / m_block_samples + 1) * m_block_samples;
    auto fail = [&](const std::string& why) {
        throw Error("sample buffer: block of samples " + std::to_string(block_first) + " to " +
                    std::to_string(block_first + n) + " at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                    "): " + why);
    };
    if (block_first != next) fail("the pixel's next sample is " + std::to_string(next));
    if (block_first % m_block_samples != 0 && block_first != m_first_sample)
        fail("it does not start on a block boundary (blocks of " + std::to_string(m_block_samples) + ")");
    if (n == 0 || block_first + n > block_end) fail("it is empty or runs past its block");
    // Even indices in [first, first + n): half of n, and the odd one out is even when the block starts even.
    const std::uint64_t evens = n / 2 + ((n % 2 == 1 && block_first % 2 == 0) ? 1 : 0);
    if (sums.count[0] != evens) fail("its even and odd counts do not match its sample indices");
    if (p.block.total_count() > 0) p.done += p.block;
    p.block = sums;
}

RGB SampleBuffer::mean(int x, int y) const {
    const PixelSums& p = at(x, y);
    const std::uint32_t n = p.total_count();
    if (n == 0) return {};
    std::array<double, 3> m{};
    for (int c = 0; c < 3; ++c) m[static_cast<std::size_t>(c)] = (p.sum(0, c) + p.sum(1, c)) / static_cast<double>(n);
    return to_rgb(m);
}

RGB SampleBuffer::half_mean(int x, int y, int parity) const {
    const PixelSums& p = at(x, y);
    const std::uint32_t n = p.count(parity);
    if (n == 0) return {};
    std::array<double, 3> m{};
    for (int c = 0; c < 3; ++c) m[static_cast<std::size_t>(c)] = p.sum(parity, c) / static_cast<double>(n);
    return to_rgb(m);
}

RGB SampleBuffer::sample_variance(int x, int y) const {
    const PixelSums& p = at(x, y);
    const std::uint32_t n = p.total_count();
    if (n < 2) return {};
    std::array<double, 3> v{};
    for (int c = 0; c < 3; ++c) {
        const double s = p.sum(0, c) + p.sum(1, c);
        v[static_cast<std::size_t>(c)] =
            std::max(0.0, (p.sum_squares(c) - s * s / static_cast<double>(n)) / static_cast<double>(n - 1));
    }
    return to_rgb(v);
}

RGB SampleBuffer::mean_variance(int x, int y) const {
    const std::uint32_t n = count(x, y);
    return n < 2 ? RGB{} : sample_variance(x, y) / static_cast<float>(n);
}

Image SampleBuffer::mean_image() const {
    return image_of(*this, [&](int x, int y) { return mean(x, y); });
}

Image SampleBuffer::half_mean_image(int parity) const {
    return image_of(*this, [&](int x, int y) { return half_mean(x, y, parity); });
}

Image SampleBuffer::mean_variance_image() const {
    return image_of(*this, [&](int x, int y) { return mean_variance(x, y); });
}

std::vector<std::uint32_t> SampleBuffer::counts() const {
    std::vector<std::uint32_t> out;
    out.reserve(m_pixels.size());
    for (const PixelSums& p : m_pixels) out.push_back(p.total_count());
    return out;
}

std::uint64_t SampleBuffer::total_samples() const {
    std::uint64_t n = 0;
    for (const PixelSums& p : m_pixels) n += p.total_count();
    return n;
}

std::uint32_t SampleBuffer::min_count() const {
    std::uint32_t m = std::numeric_limits<std::uint32_t>::max();
    for (const PixelSums& p : m_pixels) m = std::min(m, p.total_count());
    return m_pixels.empty() ? 0 : m;
}

void SampleBuffer::merge(const SampleBuffer& other) {
    if (other.m_width != m_width || other.m_height != m_height)
        throw Error("sample buffer merge: size " + std::to_string(other.m_width) + "x" +
                    std::to_string(other.m_height) + " differs from " + std::to_string(m_width) + "x" +
                    std::to_string(m_height));
    for (std::size_t i = 0; i < m_pixels.size(); ++i) {
        PixelSums& a = m_pixels[i];
        const PixelSums& b = other.m_pixels[i];
        a.done += a.block;
        a.done += b.done;
        a.block = b.block;
    }
}

bool operator==(const SampleBuffer& a, const SampleBuffer& b) {
    if (a.m_width != b.m_width || a.m_height != b.m_height || a.m_first_sample != b.m_first_sample ||
        a.m_block_samples != b.m_block_samples)
        return false;
    // Bytes, not values: a NaN sum must equal itself, and -0 must differ from +0, for "the same image".
    return std::memcmp(a.m_pixels.data(), b.m_pixels.data(), a.m_pixels.size() * sizeof(PixelSums)) == 0;
}

}  // namespace rtlab
