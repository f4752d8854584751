#include "image_plane.hpp"
#include "noisy_sphere.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/render/renderer.hpp>
#include <rtlab/render/thin_lens_camera.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <span>
#include <string>
#include <thread>

#include <unistd.h>

using namespace rtlab;
using test::same_bytes;

namespace {

/// A sphere with hash noise in its shading and a few fake secondary rays: enough structure for the
/// adaptive pattern to refine, and counts for every ray kind.
class NoisySphere final : public RadianceSource {
public:
    RGB radiance(const Ray& r, const SampleKey& key, RayCounters& counters) const override {
        return test::noisy_sphere(r, counters, [&](float light) {
            return RGB(light * 3.0f, light * sample_uniform(key, 0), 0.5f * sample_uniform(key, 1));
        });
    }
};

}  // namespace

TEST_CASE("1 2 and 8 threads give the same image byte for byte", "[renderer]") {
    const ThinLensCamera camera(
        {.eye = {0, 0, 0}, .look_at = {0, 0, -4}, .vertical_fov_degrees = 40.0f, .width = 53, .height = 37},
        {.aperture = 0.2f, .focus_distance = 3.5f});
    const NoisySphere scene;
    for (PixelPattern p : {PixelPattern::none, PixelPattern::jittered, PixelPattern::random, PixelPattern::adaptive}) {
        INFO(pixel_pattern_name(p));
        RenderSettings s;
        s.pattern = p;
        s.spp = 5;
        s.adaptive = {3, 0.2f};
        s.seed = 99;
        s.tile_size = 8;
        s.threads = 1;
        const RenderResult one = render(camera, scene, s);
        CHECK(one.stats.rays.camera > 0);
        CHECK(one.stats.rays.shadow > 0);
        CHECK(one.stats.rays.reflected > 0);
        CHECK(one.stats.rays.refracted > 0);
        for (int threads : {2, 8}) {
            s.threads = threads;
            std::mutex mutex;
            std::set<std::thread::id> workers;
            const FunctionRadiance watched([&](const Ray& r, const SampleKey& k, RayCounters& c) {
                {
                    std::lock_guard lock(mutex);
                    workers.insert(std::this_thread::get_id());
                }
                // Short sleeps let the other threads of the arena take tiles even on a 2-core machine.
                thread_local int calls = 0;
                if (++calls % 64 == 0) std::this_thread::sleep_for(std::chrono::microseconds(500));
                return scene.radiance(r, k, c);
            });
            const RenderResult many = render(camera, watched, s);
            INFO(threads << " threads");
            // The arena bounds the workers (how many of them get a tile depends on the machine).
            CHECK(workers.size() <= static_cast<std::size_t>(threads));
            std::printf("determinism %s: %d threads asked, %zu took tiles\n",
                        std::string(pixel_pattern_name(p)).c_str(), threads, workers.size());
            CHECK(same_bytes(one.image, many.image));
            CHECK(one.samples == many.samples);
            CHECK(one.stats.rays == many.stats.rays);
        }
        // The tile size changes nothing but the adaptive pattern's shared-corner accounting.
        s.tile_size = 13;
        s.threads = 2;
        const RenderResult other_tiles = render(camera, scene, s);
        CHECK(same_bytes(one.image, other_tiles.image));
        // And another seed changes the noise.
        s.seed = 100;
        CHECK_FALSE(same_bytes(one.image, render(camera, scene, s).image));
    }
}

namespace {

/// NoisySphere that records the groups radiance_batch() is handed (their keys), each sample's radiance its own.
class GroupedNoisySphere final : public RadianceSource {
public:
    RGB radiance(const Ray& r, const SampleKey& key, RayCounters& counters) const override {
        return m_sphere.radiance(r, key, counters);
    }
    void radiance_batch(std::span<const CameraSample> samples, std::span<RGB> out,
                        RayCounters& counters) const override {
        std::vector<SampleKey> keys;
        for (std::size_t i = 0; i < samples.size(); ++i) {
            keys.push_back(samples[i].stream.key());
            out[i] = m_sphere.radiance(samples[i].ray, keys.back(), counters);
        }
        std::lock_guard lock(m_mutex);
        m_groups.push_back(std::move(keys));
    }
    bool traces_batches() const override { return true; }
    std::vector<std::vector<SampleKey>> groups() const {
        std::lock_guard lock(m_mutex);
        return m_groups;
    }

private:
    NoisySphere m_sphere;
    mutable std::mutex m_mutex;
    mutable std::vector<std::vector<SampleKey>> m_groups;
};

}  // namespace

TEST_CASE("adaptive sampling hands its camera rays over in groups and renders the same image", "[renderer]") {
    const ThinLensCamera camera(
        {.eye = {0, 0, 0}, .look_at = {0, 0, -4}, .vertical_fov_degrees = 40.0f, .width = 29, .height = 17},
        {.aperture = 0.2f, .focus_distance = 3.5f});
    for (const int tile : {5, 8, 64}) {
        INFO("tile " << tile);
        RenderSettings s;
        s.pattern = PixelPattern::adaptive;
        s.adaptive = {3, 0.2f};
        s.seed = 7;
        s.tile_size = tile;  // 5: odd rows of pixels in a tile, a last pair cut short
        s.threads = 2;
        const GroupedNoisySphere grouped;
        const RenderResult with = render(camera, grouped, s);
        s.packets = false;
        const GroupedNoisySphere single;
        const RenderResult without = render(camera, single, s);
        CHECK(single.groups().empty());
        CHECK(same_bytes(with.image, without.image));
        CHECK(with.samples == without.samples);
        CHECK(with.stats.rays == without.stats.rays);
        // Every camera ray in a group: the pixel corners of every tile two rows of pixels at a time, with up to
        // 3 (tile + 1) rays, then the points inside the pixels that the squares whose corners differ need, level by
        // level, with at most as many rays as one pixel may trace (9 x 9 at depth 3).
        std::size_t grouped_samples = 0, corner_samples = 0, corner_groups = 0, expected_corners = 0,
                    expected_corner_groups = 0, largest_inner_group = 0;
        for (const auto& keys : grouped.groups()) {
            grouped_samples += keys.size();
            const bool corners =
                std::all_of(keys.begin(), keys.end(), [](const SampleKey& k) { return k.x % 8 == 0 && k.y % 8 == 0; });
            if (corners) {
                corner_samples += keys.size();
                ++corner_groups;
                CHECK(keys.size() <= 3 * static_cast<std::size_t>(tile + 1));
            } else {
                largest_inner_group = std::max(largest_inner_group, keys.size());
            }
        }
        for (int y0 = 0; y0 < camera.height(); y0 += tile)
            for (int x0 = 0; x0 < camera.width(); x0 += tile) {
                const auto columns = static_cast<std::size_t>(std::min(tile, camera.width() - x0));
                const auto rows = static_cast<std::size_t>(std::min(tile, camera.height() - y0));
                expected_corners += (columns + 1) * (rows + 1);
                expected_corner_groups += (rows + 1) / 2;
            }
        CHECK(grouped_samples == with.stats.rays.camera);
        CHECK(corner_samples == expected_corners);
        CHECK(corner_groups == expected_corner_groups);
        CHECK(largest_inner_group > 0);
        CHECK(largest_inner_group <= 81);
        CHECK(with.stats.rays.camera > 2 * expected_corners);  // the noise made it refine
    }
}

TEST_CASE("the renderer reports progress for every tile and ray counts per kind", "[renderer]") {
    const test::ImagePlaneCamera camera(50, 30);
    const FunctionRadiance source([](const Ray&, const SampleKey&, RayCounters& c) {
        c.shadow += 2;
        ++c.reflected;
        return RGB(1.0f);
    });
    RenderSettings s;
    s.pattern = PixelPattern::grid;
    s.spp = 4;
    s.tile_size = 16;  // 4 x 2 tiles
    s.threads = 2;
    std::vector<int> seen;
    RenderCallbacks cb;
    std::uint64_t last_rays = 0;
    bool monotone = true;
    cb.progress = [&](const RenderProgress& p) {
        seen.push_back(p.tiles_done);
        CHECK(p.tiles_total == 8);
        monotone = monotone && p.rays.total() > last_rays;
        last_rays = p.rays.total();
    };
    const RenderResult res = render(camera, source, s, cb);
    CHECK(seen == std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8});
    CHECK(monotone);
    CHECK(res.stats.rays.camera == 50 * 30 * 4);
    CHECK(res.stats.rays.shadow == 2 * 50 * 30 * 4);
    CHECK(res.stats.rays.reflected == 50 * 30 * 4);
    CHECK(res.stats.rays.refracted == 0);
    CHECK(last_rays == res.stats.rays.total());
    CHECK_FALSE(res.stats.cancelled);
    CHECK(res.stats.seconds > 0.0);
    CHECK(res.stats.rays_per_second() > 0.0);
    CHECK(res.image.at(49, 29) == RGB(1.0f));
}

TEST_CASE("a stopped render returns promptly with the finished tiles and writes nothing", "[renderer]") {
    // About 100 us per ray: the whole 256 x 256 image would take 6.5 s on one thread.
    const FunctionRadiance slow([](const Ray&, const SampleKey&, RayCounters&) {
        const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(100);
        while (std::chrono::steady_clock::now() < until) {
        }
        return RGB(1.0f);
    });
    const auto dir =
        std::filesystem::temp_directory_path() / ("rtlab_render_cancel_test_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (int threads : {1, 2}) {
        INFO(threads << " threads");
        std::atomic<bool> stop{false};
        std::chrono::steady_clock::time_point stopped_at;
        RenderCallbacks cb;
        cb.stop = &stop;
        cb.progress = [&](const RenderProgress& p) {
            if (p.tiles_done == 3) {
                stopped_at = std::chrono::steady_clock::now();
                stop = true;
            }
        };
        RenderSettings s;
        s.tile_size = 16;
        s.threads = threads;
        const RenderResult res = render(test::ImagePlaneCamera(256, 256), slow, s, cb);
        const double after_stop = std::chrono::duration<double>(std::chrono::steady_clock::now() - stopped_at).count();
        // A worker finishes at most its current pixel (100 us) after the stop.
        CHECK(after_stop < 0.25);
        CHECK(res.stats.cancelled);
        CHECK(res.stats.tiles_done >= 3);
        CHECK(res.stats.tiles_done < res.stats.tiles_total);
        const auto rendered = std::count_if(res.samples.begin(), res.samples.end(), [](auto n) { return n > 0; });
        CHECK(rendered >= 3 * 256);
        CHECK(rendered < 256 * 256 / 4);
        CHECK(static_cast<std::uint64_t>(rendered) == res.stats.rays.camera);
        CHECK(res.image.at(0, 0) == RGB(1.0f));
        CHECK(res.image.at(255, 255) == RGB(0.0f));
        CHECK(std::filesystem::is_empty(dir));
        // What was rendered can be written whole.
        write_render_output(res.image, dir / "partial.pfm");
        CHECK(read_pfm(dir / "partial.pfm").at(0, 0) == RGB(1.0f));
        std::filesystem::remove(dir / "partial.pfm");
    }
    std::filesystem::remove_all(dir);
}

namespace {

/// A FunctionRadiance that may claim radiance_batch() is faster (RadianceSource::traces_batches).
class BatchingFunction final : public RadianceSource {
public:
    BatchingFunction(FunctionRadiance::Function f, bool batches) : m_f(std::move(f)), m_batches(batches) {}
    RGB radiance(const Ray& r, const SampleKey& key, RayCounters& counters) const override {
        return m_f(r, key, counters);
    }
    bool traces_batches() const override { return m_batches; }

private:
    FunctionRadiance::Function m_f;
    bool m_batches;
};

}  // namespace

TEST_CASE("a stop during an adaptive render ends it within one pixel per thread", "[renderer]") {
    // Pure noise at depth 6: every pixel traces up to 65^2 = 4,225 rays, the whole image 16.8 million.
    for (const bool batches : {false, true}) {
        INFO("groups " << batches);
        std::atomic<bool> stop{false};
        std::atomic<int> calls{0};
        const BatchingFunction noise(
            [&](const Ray&, const SampleKey& key, RayCounters&) {
                if (++calls == 5000) stop = true;
                return RGB(sample_uniform(key, 0));
            },
            batches);
        RenderSettings s;
        s.pattern = PixelPattern::adaptive;
        s.adaptive = {6, 0.1f};
        s.threads = 2;
        RenderCallbacks cb;
        cb.stop = &stop;
        const RenderResult res = render(test::ImagePlaneCamera(64, 64), noise, s, cb);
        CHECK(res.stats.cancelled);
        CHECK(res.stats.tiles_done == 0);
        CHECK(res.stats.rays.camera == static_cast<std::uint64_t>(calls.load()));
        // One pixel's rays, or one group's (no larger), per thread after the stop.
        CHECK(res.stats.rays.camera < 5000 + 2 * 65 * 65);
        const auto rendered = std::count_if(res.samples.begin(), res.samples.end(), [](auto n) { return n > 0; });
        CHECK(rendered <= 4);
        // Ray by ray, the pixels traced before the stop are kept; in groups a row's inner points are traced before
        // its first pixel is done, so 5,000 rays may end no pixel of a noisy row.
        if (!batches) CHECK(rendered >= 1);
    }
}

TEST_CASE("bad render settings are rejected with a reason", "[renderer]") {
    using Catch::Matchers::Contains;
    const test::ImagePlaneCamera camera(8, 8);
    const FunctionRadiance black([](const Ray&, const SampleKey&, RayCounters&) { return RGB(); });
    auto with = [](auto change) {
        RenderSettings s;
        change(s);
        return s;
    };
    CHECK_THROWS_WITH(render(camera, black, with([](RenderSettings& s) { s.tile_size = -1; })), Contains("tile size"));
    CHECK_THROWS_WITH(render(camera, black, with([](RenderSettings& s) { s.threads = -1; })), Contains("thread"));
    CHECK_THROWS_WITH(render(camera, black, with([](RenderSettings& s) {
                                 s.pattern = PixelPattern::jittered;
                                 s.spp = 0;
                             })),
                      Contains("samples per pixel"));
    CHECK_THROWS_WITH(render(camera, black, with([](RenderSettings& s) {
                                 s.pattern = PixelPattern::adaptive;
                                 s.adaptive.max_depth = kMaxAdaptiveDepth + 1;
                             })),
                      Contains("adaptive depth"));
    CHECK_THROWS_WITH(render(camera, black, with([](RenderSettings& s) {
                                 s.pattern = PixelPattern::adaptive;
                                 s.adaptive.threshold = std::nanf("");
                             })),
                      Contains("threshold"));
    CHECK_THROWS_WITH(render(test::ImagePlaneCamera(0, 8), black, RenderSettings{}), Contains("image size"));
    CHECK_THROWS_WITH(render(test::ImagePlaneCamera(1 << 17, 1), black, with([](RenderSettings& s) {
                                 s.pattern = PixelPattern::adaptive;
                                 s.adaptive.max_depth = 8;
                             })),
                      Contains("too large"));
    // An exception from the radiance source reaches the caller.
    const FunctionRadiance throws(
        [](const Ray&, const SampleKey&, RayCounters&) -> RGB { throw Error("scene broke"); });
    CHECK_THROWS_WITH(render(camera, throws, RenderSettings{}), Contains("scene broke"));
}

TEST_CASE("tile size 0 picks 64 32 or 16 pixels from the image size alone", "[renderer]") {
    CHECK(auto_tile_size(1280, 960) == 64);  // 300 tiles
    CHECK(auto_tile_size(1024, 512) == 64);  // exactly 128
    CHECK(auto_tile_size(1024, 511) == 32);
    CHECK(auto_tile_size(640, 480) == 32);
    CHECK(auto_tile_size(320, 240) == 16);
    CHECK(auto_tile_size(8, 8) == 16);
    // The render reports the tiles it cut.
    const test::ImagePlaneCamera camera(640, 480);
    const FunctionRadiance black([](const Ray&, const SampleKey&, RayCounters&) { return RGB(); });
    RenderSettings s;
    s.threads = 1;
    CHECK(render(camera, black, s).stats.tiles_total == 20 * 15);
}
