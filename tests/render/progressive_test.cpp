#include "image_plane.hpp"
#include "noisy_sphere.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/progressive.hpp>
#include <rtlab/render/renderer.hpp>
#include <rtlab/render/thin_lens_camera.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <tuple>

using namespace rtlab;
using namespace rtlab::test;

namespace {

/// A sphere whose shading draws two of the integrator's own pairs from the sample's stream, and counts fake
/// secondary rays: the image depends on the pixel offset, the lens point and the integrator's dimensions.
class StreamSphere final : public RadianceSource {
public:
    RGB radiance(const Ray& r, const SampleKey& key, RayCounters& counters) const override {
        return sample_radiance(CameraSample{r, SampleStream(SampleSequence::independent, key)}, counters);
    }
    RGB sample_radiance(const CameraSample& s, RayCounters& counters) const override {
        return noisy_sphere(s.ray, counters, [&](float light) {
            const Vec2 u = s.stream.get2d(kFirstIntegratorPair), v = s.stream.get2d(kFirstIntegratorPair + 1);
            return RGB(light * 3.0f * u.x, light * v.y, 0.5f * u.y * v.x);
        });
    }
};

ThinLensCamera small_camera(int w, int h) {
    return ThinLensCamera(
        {.eye = {0, 0, 0}, .look_at = {0, 0, -4}, .vertical_fov_degrees = 40.0f, .width = w, .height = h},
        {.aperture = 0.2f, .focus_distance = 3.5f});
}

ProgressiveSettings settings_for(int spp, int pass_samples, int threads, int tile_size = 7) {
    ProgressiveSettings s;
    s.spp = spp;
    s.pass_samples = pass_samples;
    s.threads = threads;
    s.tile_size = tile_size;
    s.seed = 1234;
    return s;
}

}  // namespace

TEST_CASE("progressive renders are the same bytes for 1 and 2 threads and any tile size", "[progressive]") {
    const ThinLensCamera camera = small_camera(23, 17);
    const StreamSphere scene;
    for (SampleSequence q : {SampleSequence::sobol, SampleSequence::independent}) {
        ProgressiveSettings s = settings_for(6, 2, 1);
        s.sequence = q;
        const ProgressiveResult one = render_progressive(camera, scene, s);
        CHECK(one.stats.rays.camera == 23u * 17u * 6u);
        CHECK(one.stats.rays.shadow > 0);
        CHECK_FALSE(one.stats.cancelled);
        s.threads = 2;
        for (int tile : {7, 16, 1}) {
            s.tile_size = tile;
            const ProgressiveResult two = render_progressive(camera, scene, s);
            CHECK(two.buffer == one.buffer);
            CHECK(same_bytes(two.image, one.image));
            CHECK(two.stats.rays == one.stats.rays);
        }
    }
}

TEST_CASE("8 spp in one pass or 8 passes of 1 or 0 to 3 then 3 to 8 give the same bytes", "[progressive]") {
    const ThinLensCamera camera = small_camera(19, 13);
    const StreamSphere scene;
    const ProgressiveResult whole = render_progressive(camera, scene, settings_for(8, 0, 2));
    const ProgressiveResult ones = render_progressive(camera, scene, settings_for(8, 1, 2));
    CHECK(ones.buffer == whole.buffer);
    CHECK(same_bytes(ones.image, whole.image));
    CHECK(ones.stats.rays == whole.stats.rays);

    ProgressiveRenderer split(camera, scene, settings_for(8, 0, 2));
    CHECK(split.render_to(3));
    CHECK(split.buffer().min_count() == 3);
    CHECK(split.render_to(8));
    CHECK(split.buffer() == whole.buffer);
    CHECK(same_bytes(split.buffer().mean_image(), whole.image));
    CHECK(split.stats().rays == whole.stats.rays);
    // Asking for fewer samples than the pixels hold adds nothing.
    CHECK(split.render_to(5));
    CHECK(split.buffer() == whole.buffer);
}

TEST_CASE("N spp gives exactly N samples in every pixel from the first sample asked for", "[progressive]") {
    const test::ImagePlaneCamera camera(9, 5);
    const StreamSphere scene;
    for (int spp : {1, 3, 8, 13}) {
        ProgressiveSettings s = settings_for(spp, 4, 2);
        s.first_sample = 5;
        const ProgressiveResult r = render_progressive(camera, scene, s);
        INFO("spp " << spp);
        CHECK(r.buffer.first_sample() == 5);
        CHECK(r.buffer.min_count() == static_cast<std::uint32_t>(spp));
        for (std::uint32_t c : r.buffer.counts()) CHECK(c == static_cast<std::uint32_t>(spp));
        CHECK(r.buffer.next_sample(8, 4) == static_cast<std::uint32_t>(5 + spp));
        // Samples 5.. have parities odd, even, odd...: the odd half gets the extra one.
        CHECK(r.buffer.at(3, 2).count(1) == static_cast<std::uint32_t>((spp + 1) / 2));
        CHECK(r.stats.rays.camera == 45u * static_cast<std::uint64_t>(spp));
    }
    CHECK_THROWS_AS(render_progressive(camera, scene, settings_for(0, 0, 1)), Error);
    ProgressiveSettings bad = settings_for(2, 0, 1);
    bad.first_sample = 0xffffffffu;
    CHECK_THROWS_WITH(render_progressive(camera, scene, bad), Catch::Contains("below 2^32"));
    bad = settings_for(2, -1, 1);
    CHECK_THROWS_WITH(render_progressive(camera, scene, bad), Catch::Contains("per pass"));
}

TEST_CASE("a sample range rendered alone holds the same samples as in a whole render", "[progressive]") {
    // Samples [3, 8) alone: each pixel's values are those of the whole render's samples 3..7, so its sums are the
    // whole render's minus those of [0, 3) up to rounding, and its counts and parities are exact.
    const test::ImagePlaneCamera camera(6, 4);
    const StreamSphere scene;
    const ProgressiveResult whole = render_progressive(camera, scene, settings_for(8, 0, 1));
    const ProgressiveResult head = render_progressive(camera, scene, settings_for(3, 0, 1));
    ProgressiveSettings s = settings_for(5, 0, 1);
    s.first_sample = 3;
    const ProgressiveResult tail = render_progressive(camera, scene, s);
    SampleBuffer merged = head.buffer;
    merged.merge(tail.buffer);
    CHECK(merged.counts() == whole.buffer.counts());
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x)
            for (int c = 0; c < 3; ++c) {
                CHECK(merged.mean(x, y)[c] == Approx(whole.image.at(x, y)[c]).epsilon(1e-6).margin(1e-7));
                CHECK(merged.at(x, y).sum_squares(c) == Approx(whole.buffer.at(x, y).sum_squares(c)).epsilon(1e-12));
            }
    CHECK_THROWS_AS(merged.merge(SampleBuffer(5, 4)), Error);
}

TEST_CASE("tile pass and progress callbacks come as documented", "[progressive]") {
    const test::ImagePlaneCamera camera(20, 10);
    const StreamSphere scene;
    ProgressiveSettings s = settings_for(5, 2, 2, 8);  // 3 x 2 tiles, passes [0, 2) [2, 4) [4, 5)
    std::mutex mutex;
    std::map<std::pair<int, int>, int> tiles;  // (pass, tile origin index) -> calls
    std::vector<std::tuple<int, std::uint32_t, std::uint32_t>> passes;
    std::vector<int> progress_done;
    int progress_total = -1;
    int concurrent = 0, max_concurrent = 0;
    ProgressiveCallbacks cb;
    cb.tile = [&](const TileUpdate& t) {
        ++concurrent;
        max_concurrent = std::max(max_concurrent, concurrent);
        {
            std::lock_guard lock(mutex);
            ++tiles[{t.pass, (t.y0 / 8) * 3 + t.x0 / 8}];
        }
        CHECK(t.x1 - t.x0 == (t.x0 == 16 ? 4 : 8));
        CHECK(t.y1 - t.y0 == (t.y0 == 8 ? 2 : 8));
        CHECK(t.pass_end == std::min<std::uint32_t>(5, 2u * static_cast<std::uint32_t>(t.pass + 1)));
        // The tile's pixels are complete for the pass.
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x) CHECK(t.buffer.count(x, y) == t.pass_end);
        --concurrent;
    };
    cb.pass = [&](const PassUpdate& p) {
        passes.emplace_back(p.pass, p.pass_begin, p.pass_end);
        CHECK(p.buffer.min_count() == p.pass_end);
        CHECK(p.stats.rays.camera == 200u * p.pass_end);
    };
    cb.progress = [&](const RenderProgress& p) {
        progress_done.push_back(p.tiles_done);
        if (progress_total < 0) progress_total = p.tiles_total;
        CHECK(p.tiles_total == progress_total);
    };
    const ProgressiveResult r = render_progressive(camera, scene, s, cb);
    CHECK(max_concurrent == 1);
    CHECK(tiles.size() == 18);
    for (const auto& [k, n] : tiles) CHECK(n == 1);
    CHECK(passes == std::vector<std::tuple<int, std::uint32_t, std::uint32_t>>{{0, 0, 2}, {1, 2, 4}, {2, 4, 5}});
    CHECK(progress_total == 18);
    REQUIRE(progress_done.size() == 18);
    for (std::size_t i = 0; i < progress_done.size(); ++i) CHECK(progress_done[i] == static_cast<int>(i) + 1);
    CHECK(r.stats.tiles_done == 18);
    CHECK(r.stats.tiles_total == 18);
}

TEST_CASE("a stopped render returns early says so and can be resumed to the same bytes", "[progressive]") {
    const ThinLensCamera camera = small_camera(24, 16);
    const StreamSphere scene;
    const ProgressiveSettings s = settings_for(6, 1, 2, 8);
    const ProgressiveResult whole = render_progressive(camera, scene, s);

    std::atomic<bool> stop{false};
    ProgressiveCallbacks cb;
    cb.stop = &stop;
    int passes = 0;
    cb.pass = [&](const PassUpdate&) { ++passes; };
    cb.tile = [&](const TileUpdate& t) {
        if (t.pass == 2) stop = true;  // in the third pass
    };
    ProgressiveRenderer renderer(camera, scene, s);
    renderer.plan_passes(6);
    bool complete = true;
    std::uint32_t end = 1;
    for (; end <= 6 && complete; ++end) complete = renderer.render_to(end, cb, static_cast<int>(end - 1));
    CHECK_FALSE(complete);
    CHECK(renderer.stats().cancelled);
    CHECK(end == 4);  // the loop stopped after the third pass
    CHECK(renderer.stats().tiles_done < renderer.stats().tiles_total);
    CHECK(renderer.stats().rays.camera < whole.stats.rays.camera);
    CHECK(renderer.buffer().min_count() == 2);
    // Resumed: the pixels the stopped pass missed catch up first, in sample order.
    stop = false;
    CHECK(renderer.render_to(6));
    CHECK_FALSE(renderer.stats().cancelled);
    CHECK(renderer.buffer() == whole.buffer);
    CHECK(renderer.stats().rays == whole.stats.rays);

    // Through render_progressive: cancelled is reported, the counts say what each pixel got.
    stop = false;
    ProgressiveCallbacks cb2;
    cb2.stop = &stop;
    cb2.tile = [&](const TileUpdate&) { stop = true; };
    const ProgressiveResult r = render_progressive(camera, scene, s, cb2);
    CHECK(r.stats.cancelled);
    CHECK(r.buffer.min_count() == 0);
    CHECK(r.stats.tiles_done < r.stats.tiles_total);
}

TEST_CASE("a stop request returns within a group of samples not a whole tile", "[progressive]") {
    // Each sample sleeps 0.2 ms: one 64 x 64 tile of 16 samples would take 13 s on a thread, one group (two rows
    // of the tile at one sample index) 26 ms. The stop comes 50 ms in.
    const test::ImagePlaneCamera camera(64, 64);
    const FunctionRadiance slow([](const Ray&, const SampleKey&, RayCounters&) {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        return RGB(1.0f);
    });
    std::atomic<bool> stop{false};
    ProgressiveCallbacks cb;
    cb.stop = &stop;
    const auto start = std::chrono::steady_clock::now();
    std::thread stopper([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        stop = true;
    });
    const ProgressiveResult r = render_progressive(camera, slow, settings_for(16, 0, 2, 64), cb);
    stopper.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(r.stats.cancelled);
    CHECK(seconds < 2.0);
    CHECK(r.stats.rays.camera < 64u * 64u);
}

TEST_CASE("the batch entry point gets coherent groups and gives the single-sample answers", "[progressive]") {
    // Groups are one sample index over at most two neighbouring rows of one tile.
    class Batching final : public RadianceSource {
    public:
        RGB radiance(const Ray& r, const SampleKey& key, RayCounters& c) const override {
            return m_inner.radiance(r, key, c);
        }
        RGB sample_radiance(const CameraSample& s, RayCounters& c) const override {
            return m_inner.sample_radiance(s, c);
        }
        void radiance_batch(std::span<const CameraSample> samples, std::span<RGB> out, RayCounters& c) const override {
            // Catch's assertions are not thread-safe: record, check on the test's thread.
            std::set<std::uint32_t> ys, indices;
            for (const CameraSample& s : samples) ys.insert(s.stream.key().y), indices.insert(s.stream.key().sample);
            const bool coherent = out.size() == samples.size() && indices.size() == 1 && ys.size() <= 2 &&
                                  *ys.rbegin() - *ys.begin() <= 1 && samples.size() <= 2 * 8;
            {
                std::lock_guard lock(m_mutex);
                ++m_batches;
                m_largest = std::max(m_largest, samples.size());
                m_incoherent += coherent ? 0 : 1;
            }
            // Back to front: the answers must not depend on the order within a group.
            for (std::size_t i = samples.size(); i-- > 0;) out[i] = m_inner.sample_radiance(samples[i], c);
        }
        mutable std::mutex m_mutex;
        mutable int m_batches = 0;
        mutable std::size_t m_largest = 0;
        mutable int m_incoherent = 0;

    private:
        StreamSphere m_inner;
    };
    const ThinLensCamera camera = small_camera(21, 11);
    const Batching batching;
    const StreamSphere plain;
    const ProgressiveSettings s = settings_for(3, 0, 2, 8);
    const ProgressiveResult a = render_progressive(camera, batching, s);
    const ProgressiveResult b = render_progressive(camera, plain, s);
    CHECK(a.buffer == b.buffer);
    CHECK(a.stats.rays == b.stats.rays);
    CHECK(batching.m_incoherent == 0);
    CHECK(batching.m_largest == 16);
    CHECK(batching.m_batches == 3 * 3 * 6);  // 3 samples x 3 tile columns x 6 row pairs (4 + 2 per tile row)
}

TEST_CASE("a known function of the pixel offset integrates to its analytic pixel mean", "[progressive]") {
    // f(X, Y) = 2 + sin(1.3 X + 0.7 Y) + X Y / 100 over image positions: its mean over pixel [x, x + 1] x [y, y + 1]
    // is 2 + (sin(a x + b y) - sin(a x + a + b y) - sin(a x + b y + b) + sin(a (x + 1) + b (y + 1))) / (a b) ...
    // computed below in double, with (x + 1/2)(y + 1/2) / 100 for the product term.
    const double a = 1.3, b = 0.7;
    auto f = [&](double X, double Y) { return 2.0 + std::sin(a * X + b * Y) + X * Y / 100.0; };
    auto pixel_mean = [&](int x, int y) {
        auto F = [&](double X, double Y) { return -std::sin(a * X + b * Y) / (a * b); };  // d2F/dXdY = sin
        const double s = F(x + 1, y + 1) - F(x, y + 1) - F(x + 1, y) + F(x, y);
        return 2.0 + s + (x + 0.5) * (y + 0.5) / 100.0;
    };
    const FunctionRadiance source([&](const Ray& r, const SampleKey&, RayCounters&) {
        return RGB(static_cast<float>(f(r.origin.x, r.origin.y)));
    });
    const test::ImagePlaneCamera camera(16, 16);
    auto rms_error = [&](SampleSequence q) {
        ProgressiveSettings s = settings_for(64, 0, 2, 8);
        s.sequence = q;
        const ProgressiveResult r = render_progressive(camera, source, s);
        double se = 0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const double e = static_cast<double>(r.image.at(x, y).r) - pixel_mean(x, y);
                se += e * e;
            }
        return std::sqrt(se / 256.0);
    };
    const double sobol = rms_error(SampleSequence::sobol), random = rms_error(SampleSequence::independent);
    std::printf(
        "pixel means of 2 + sin(1.3 X + 0.7 Y) + XY/100 at 64 spp, RMS error over 256 pixels: sobol %.3g, "
        "independent %.3g\n",
        sobol, random);
    // Independent samples: the per-sample sd over a pixel is about 0.3, so the RMS error is near 0.3 / 8 = 0.04;
    // scrambled (0,2) points on this smooth integrand about 64^-1.5 of it. The bound separates them by a wide margin.
    const double bound = 2e-3;
    CHECK(sobol < bound);
    CHECK(random > 5 * bound);
}

TEST_CASE("the sample buffer gives means halves and variances of the samples added", "[progressive]") {
    SampleBuffer buffer(2, 1, 4);
    const float values[] = {1.0f, 3.0f, 2.0f, 6.0f, 4.0f};  // samples 4..8: even 1, 2, 4; odd 3, 6
    for (std::uint32_t i = 0; i < 5; ++i) buffer.add(1, 0, 4 + i, RGB(values[i], 2.0f * values[i], 0.0f));
    CHECK(buffer.count(1, 0) == 5);
    CHECK(buffer.count(0, 0) == 0);
    CHECK(buffer.next_sample(1, 0) == 9);
    CHECK(buffer.mean(1, 0) == RGB(3.2f, 6.4f, 0.0f));
    CHECK(buffer.half_mean(1, 0, 0).r == Approx(7.0f / 3.0f));
    CHECK(buffer.half_mean(1, 0, 1).r == 4.5f);
    // Unbiased variance of 1, 3, 2, 6, 4: mean 3.2, squared deviations 4.84 + 0.04 + 1.44 + 7.84 + 0.64 = 14.8.
    CHECK(buffer.sample_variance(1, 0).r == Approx(14.8f / 4.0f));
    CHECK(buffer.sample_variance(1, 0).g == Approx(4.0f * 14.8f / 4.0f));
    CHECK(buffer.mean_variance(1, 0).r == Approx(14.8f / 20.0f));
    CHECK(buffer.mean(0, 0) == RGB());
    CHECK(buffer.mean_variance(0, 0) == RGB());
    CHECK(buffer.mean_image().at(1, 0) == buffer.mean(1, 0));
    CHECK(buffer.half_mean_image(1).at(1, 0) == buffer.half_mean(1, 0, 1));
    CHECK(buffer.mean_variance_image().at(1, 0) == buffer.mean_variance(1, 0));
    CHECK(buffer.min_count() == 0);
    CHECK_THROWS_AS(SampleBuffer(0, 3), Error);
}

TEST_CASE("the sobol pattern renders progressively through render", "[progressive]") {
    const ThinLensCamera camera = small_camera(15, 9);
    const StreamSphere scene;
    RenderSettings rs;
    rs.pattern = parse_pixel_pattern("sobol");
    rs.spp = 4;
    rs.seed = 1234;
    rs.tile_size = 7;
    rs.threads = 2;
    const RenderResult r = render(camera, scene, rs);
    const ProgressiveResult p = render_progressive(camera, scene, settings_for(4, 0, 1));
    CHECK(same_bytes(r.image, p.image));
    REQUIRE(r.buffer);
    CHECK(*r.buffer == p.buffer);
    CHECK(r.samples == std::vector<std::uint32_t>(15 * 9, 4));
    CHECK(r.stats.rays == p.stats.rays);
    // The pixel offsets are the stream's first pair, as pixel_samples reports them.
    const std::vector<Vec2> offsets = pixel_samples(PixelPattern::sobol, 4, SampleKey{1234, 3, 2, 0, 0});
    REQUIRE(offsets.size() == 4);
    for (std::uint32_t i = 0; i < 4; ++i)
        CHECK(offsets[i] == SampleStream(SampleSequence::sobol, {1234, 3, 2, i, 0}).get2d(kPixelPair));
    rs.pattern = PixelPattern::jittered;
    CHECK_FALSE(render(camera, scene, rs).buffer);
}
