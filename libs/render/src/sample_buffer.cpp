#include <rtlab/core/error.hpp>
#include <rtlab/render/sample_buffer.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

namespace rtlab {

namespace {

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

SampleBuffer::SampleBuffer(int width, int height, std::uint32_t first_sample)
    : m_width(width), m_height(height), m_first_sample(first_sample) {
    if (width <= 0 || height <= 0)
        throw Error("sample buffer: size must be positive, got " + std::to_string(width) + "x" +
                    std::to_string(height));
    m_pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
}

RGB SampleBuffer::mean(int x, int y) const {
    const PixelSums& p = at(x, y);
    const std::uint32_t n = p.total_count();
    if (n == 0) return {};
    std::array<double, 3> m{};
    for (std::size_t c = 0; c < 3; ++c) m[c] = (p.sum[0][c] + p.sum[1][c]) / static_cast<double>(n);
    return to_rgb(m);
}

RGB SampleBuffer::half_mean(int x, int y, int parity) const {
    const PixelSums& p = at(x, y);
    const std::size_t h = static_cast<std::size_t>(parity & 1);
    if (p.count[h] == 0) return {};
    std::array<double, 3> m{};
    for (std::size_t c = 0; c < 3; ++c) m[c] = p.sum[h][c] / static_cast<double>(p.count[h]);
    return to_rgb(m);
}

RGB SampleBuffer::sample_variance(int x, int y) const {
    const PixelSums& p = at(x, y);
    const std::uint32_t n = p.total_count();
    if (n < 2) return {};
    std::array<double, 3> v{};
    for (std::size_t c = 0; c < 3; ++c) {
        const double s = p.sum[0][c] + p.sum[1][c];
        v[c] = std::max(0.0, (p.sum_squares[c] - s * s / static_cast<double>(n)) / static_cast<double>(n - 1));
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
        for (std::size_t c = 0; c < 3; ++c) {
            a.sum[0][c] += b.sum[0][c];
            a.sum[1][c] += b.sum[1][c];
            a.sum_squares[c] += b.sum_squares[c];
        }
        a.count[0] += b.count[0];
        a.count[1] += b.count[1];
    }
}

bool operator==(const SampleBuffer& a, const SampleBuffer& b) {
    if (a.m_width != b.m_width || a.m_height != b.m_height || a.m_first_sample != b.m_first_sample) return false;
    // Bytes, not values: a NaN sum must equal itself, and -0 must differ from +0, for "the same image".
    return std::memcmp(a.m_pixels.data(), b.m_pixels.data(), a.m_pixels.size() * sizeof(PixelSums)) == 0;
}

}  // namespace rtlab
