#include "image_bytes.hpp"
#include "image_plane.hpp"

#include <rtlab/render/renderer.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <set>

using namespace rtlab;
using test::HalfPlane;
using test::ImagePlaneCamera;

namespace {

constexpr int kSize = 32;

/// RMS over all pixels of (rendered value - exact coverage of the half-plane).
double edge_error(const RenderSettings& settings, std::uint64_t* rays = nullptr) {
    const HalfPlane plane;
    const FunctionRadiance source([&](const Ray& r, const SampleKey&, RayCounters&) {
        return RGB(plane.inside(r.origin.x, r.origin.y) ? 1.0f : 0.0f);
    });
    const RenderResult res = render(ImagePlaneCamera(kSize, kSize), source, settings);
    double sum = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double e = res.image.at(x, y).r - plane.coverage(x, y);
            sum += e * e;
        }
    if (rays) *rays = res.stats.rays.camera;
    return std::sqrt(sum / (kSize * kSize));
}

RenderSettings fixed(PixelPattern p, int spp) {
    RenderSettings s;
    s.pattern = p;
    s.spp = spp;
    s.seed = 17;
    return s;
}

RenderSettings adaptive(int depth, float threshold) {
    RenderSettings s;
    s.pattern = PixelPattern::adaptive;
    s.adaptive = {depth, threshold};
    s.seed = 17;
    return s;
}

}  // namespace

TEST_CASE("the exact coverage of the test half-plane is right", "[aa]") {
    const HalfPlane plane;
    double total = 0.0;
    int partial = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double c = plane.coverage(x, y);
            REQUIRE(c >= 0.0);
            REQUIRE(c <= 1.0);
            partial += c > 0.0 && c < 1.0;
            // Against a 512 x 512 midpoint count.
            if (x % 7 == 0 && c > 0.0 && c < 1.0) {
                int in = 0;
                for (int j = 0; j < 512; ++j)
                    for (int i = 0; i < 512; ++i) in += plane.inside(x + (i + 0.5) / 512, y + (j + 0.5) / 512);
                CHECK(std::abs(in / (512.0 * 512.0) - c) < 2.0 / 512);
            }
            total += c;
        }
    // The line crosses the 32 x 32 image from y = 3.58 to y = 26.2: about 55 pixels are cut.
    CHECK(partial > 40);
    // Area below y = m x + q, clipped to the image: q * 32 + m * 32^2 / 2 (the line stays inside).
    CHECK(total == Approx(HalfPlane{}.offset * kSize + HalfPlane{}.slope * kSize * kSize / 2).epsilon(1e-9));
}

TEST_CASE("every anti-aliasing mode converges to the exact edge coverage", "[aa]") {
    const double none = edge_error(fixed(PixelPattern::none, 1));
    std::printf("aa edge RMS error, 32x32 half-plane at slope 1/sqrt(2):\n  none       1 spp: %.5f\n", none);
    for (PixelPattern p : {PixelPattern::grid, PixelPattern::random, PixelPattern::jittered}) {
        std::vector<double> err;
        for (int spp : {4, 16, 64, 256}) {
            err.push_back(edge_error(fixed(p, spp)));
            std::printf("  %-8s %3d spp: %.5f\n", std::string(pixel_pattern_name(p)).c_str(), spp, err.back());
        }
        INFO(pixel_pattern_name(p));
        CHECK(err[0] < none);
        for (std::size_t i = 1; i < err.size(); ++i) CHECK(err[i] < err[i - 1]);
        // Random converges as 1/sqrt(n) (8x over 64x the samples); grid and jittered faster.
        CHECK(err.back() < err.front() / (p == PixelPattern::random ? 5.0 : 8.0));
    }
    std::vector<double> err;
    for (int depth = 1; depth <= 5; ++depth) {
        std::uint64_t rays = 0;
        err.push_back(edge_error(adaptive(depth, 0.1f), &rays));
        std::printf("  adaptive depth %d: %.5f (%.2f rays/pixel)\n", depth, err.back(), double(rays) / (kSize * kSize));
    }
    for (std::size_t i = 1; i < err.size(); ++i) CHECK(err[i] < err[i - 1]);
    CHECK(err.back() < err.front() / 8.0);
}

TEST_CASE("adaptive sampling traces few rays where the image is flat", "[aa]") {
    const FunctionRadiance flat([](const Ray&, const SampleKey&, RayCounters&) { return RGB(0.25f, 0.5f, 2.0f); });
    RenderSettings s = adaptive(4, 0.0f);
    s.tile_size = 64;  // one tile: every lattice point is traced once
    const RenderResult res = render(ImagePlaneCamera(10, 6), flat, s);
    // Only the pixel corners: (10 + 1) x (6 + 1).
    CHECK(res.stats.rays.camera == 77);
    CHECK(res.samples[0] == 4);
    CHECK(res.samples[1] == 2);
    CHECK(res.samples[10] == 2);
    CHECK(res.samples[11] == 1);
    CHECK(res.image.at(9, 5) == RGB(0.25f, 0.5f, 2.0f));
}

namespace {

/// Renders with the adaptive pattern and checks the cap; returns the result.
RenderResult adaptive_case(const RadianceSource& source, int depth, int tile_size, int w = 12, int h = 9) {
    RenderSettings s = adaptive(depth, 0.3f);
    s.tile_size = tile_size;
    RenderResult res = render(ImagePlaneCamera(w, h), source, s);
    const std::uint32_t cap = static_cast<std::uint32_t>(((1 << depth) + 1) * ((1 << depth) + 1));
    const std::uint32_t most = *std::max_element(res.samples.begin(), res.samples.end());
    std::uint64_t sum = 0;
    for (std::uint32_t n : res.samples) sum += n;
    CHECK(most <= cap);
    CHECK(sum == res.stats.rays.camera);
    CHECK(res.stats.tiles_done == res.stats.tiles_total);
    return res;
}

/// Counts how often each lattice position was traced.
class CountingSource final : public RadianceSource {
public:
    /// batches: claims radiance_batch() is faster (RadianceSource::traces_batches), for the renderer to form groups.
    explicit CountingSource(std::function<RGB(const Ray&, const SampleKey&)> f, bool batches = false)
        : m_f(std::move(f)), m_batches(batches) {}
    bool traces_batches() const override { return m_batches; }
    RGB radiance(const Ray& r, const SampleKey& key, RayCounters&) const override {
        std::lock_guard lock(m_mutex);
        ++m_traced[{key.x, key.y}];
        return m_f(r, key);
    }
    std::size_t most_traced() const {
        std::size_t most = 0;
        for (const auto& [pos, n] : m_traced) most = std::max(most, n);
        return most;
    }
    std::size_t positions() const { return m_traced.size(); }

private:
    std::function<RGB(const Ray&, const SampleKey&)> m_f;
    bool m_batches;
    mutable std::mutex m_mutex;
    mutable std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> m_traced;
};

}  // namespace

TEST_CASE("adaptive sampling terminates on a checkerboard of one-pixel squares", "[aa]") {
    for (int depth : {0, 1, 3, 5}) {
        INFO("depth " << depth);
        const CountingSource checker([](const Ray& r, const SampleKey&) {
            const int cx = static_cast<int>(std::floor(r.origin.x)), cy = static_cast<int>(std::floor(r.origin.y));
            return RGB(((cx + cy) & 1) ? 1.0f : 0.0f);
        });
        const RenderResult res = adaptive_case(checker, depth, 64);
        // One tile: no lattice point is traced twice.
        CHECK(checker.most_traced() == 1);
        // Every pixel's right and bottom corners take the neighbouring squares' colour, so every pixel is
        // refined down to single lattice steps along those edges: the first pixel traces the
        // 2^(depth+1) + 1 points of its right and bottom edges beside the (2^depth+1)-point grid
        // of its upper-left quarter... counted exactly below for the first pixel.
        const int r = 1 << depth;
        // Squares touching the right or bottom edge split; the others (all-black interior) do not. The
        // first pixel's traced points: all points with i == r or j == r at the finest level, plus the
        // corners of the squares that were split on the way down (lattice steps r/2, r/4, ...).
        std::set<std::pair<int, int>> points;
        std::function<void(int, int, int)> walk = [&](int i, int j, int size) {
            for (auto [a, b] : {std::pair{i, j}, {i + size, j}, {i, j + size}, {i + size, j + size}})
                points.insert({a, b});
            if (size > 1 && (i + size == r || j + size == r)) {
                const int hs = size / 2;
                walk(i, j, hs);
                walk(i + hs, j, hs);
                walk(i, j + hs, hs);
                walk(i + hs, j + hs, hs);
            }
        };
        walk(0, 0, r);
        CHECK(res.samples[0] == points.size());
        // The mean of black and white corners: never 0 or 1 for a pixel whose neighbours differ.
        CHECK(res.image.at(3, 3).r > 0.0f);
    }
}

TEST_CASE("adaptive sampling terminates on pure noise at the sample cap", "[aa]") {
    for (int depth : {2, 4}) {
        INFO("depth " << depth);
        const CountingSource noise([](const Ray&, const SampleKey& key) {
            return RGB(sample_uniform(key, 0), sample_uniform(key, 1), sample_uniform(key, 2));
        });
        const int w = 12, h = 9, r = 1 << depth;
        const RenderResult res = adaptive_case(noise, depth, 64, w, h);
        // Everything is split: every lattice point of the image is traced, once.
        CHECK(noise.positions() == static_cast<std::size_t>((w * r + 1) * (h * r + 1)));
        CHECK(noise.most_traced() == 1);
        CHECK(res.samples[0] == static_cast<std::uint32_t>((r + 1) * (r + 1)));
        CHECK(res.samples[1] == static_cast<std::uint32_t>(r * (r + 1)));
        CHECK(res.samples[w + 1] == static_cast<std::uint32_t>(r * r));
    }
    // With tiles of 5 pixels, border corners are traced once by each tile that touches them.
    const CountingSource noise([](const Ray&, const SampleKey& key) { return RGB(sample_uniform(key, 0)); });
    adaptive_case(noise, 3, 5);
    CHECK(noise.most_traced() <= 4);
    // Depth 8 over a row of 12 pixels: the groups take the levels ahead up to 49,152 squares, and the recursion
    // traces the rest itself; every lattice point still once, and the image and counts those of single rays.
    auto deep_noise = [](const Ray&, const SampleKey& key) {
        return RGB(sample_uniform(key, 0), sample_uniform(key, 1), sample_uniform(key, 2));
    };
    const CountingSource grouped(deep_noise, true), single(deep_noise);
    const RenderResult with = adaptive_case(grouped, 8, 64, 12, 1);
    RenderSettings s = adaptive(8, 0.3f);
    s.packets = false;
    const RenderResult without = render(ImagePlaneCamera(12, 1), single, s);
    CHECK(grouped.most_traced() == 1);
    CHECK(grouped.positions() == single.positions());
    CHECK(grouped.positions() > static_cast<std::size_t>((12 * 256 + 1) * 257) * 99 / 100);
    CHECK(test::same_bytes(with.image, without.image));
    CHECK(with.samples == without.samples);
}

TEST_CASE("adaptive sampling terminates on NaN colours", "[aa]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const CountingSource all_nan([&](const Ray&, const SampleKey&) { return RGB(nan, nan, nan); });
    const int depth = 3, r = 1 << depth;
    const RenderResult res = adaptive_case(all_nan, depth, 64);
    CHECK(all_nan.positions() == static_cast<std::size_t>((12 * r + 1) * (9 * r + 1)));
    CHECK(std::isnan(res.image.at(5, 5).r));

    // NaN in one channel on a sparse set: refined around it, and the cap holds.
    const CountingSource some_nan([&](const Ray&, const SampleKey& key) {
        return sample_uniform(key, 0) < 0.05f ? RGB(0.5f, nan, 0.5f) : RGB(0.5f);
    });
    const RenderResult some = adaptive_case(some_nan, 4, 4);
    CHECK(some.stats.rays.camera > 12 * 9 * 4);
}
