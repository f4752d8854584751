// Rays per second of whole renders with a cheap analytic radiance function, by thread count. The
// radiance intersects three spheres and a ground plane and traces one analytic shadow ray per hit, so
// the figure measures the renderer (tiles, sampling, keys, counters) around roughly constant work.
#include <rtlab/render/renderer.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <atomic>
#include <cmath>

#include <sys/resource.h>

using namespace rtlab;

namespace {

/// CPU seconds of all the process's threads: on a loaded machine the wall-clock speed-up of 2 threads
/// says little, but equal CPU time per render at 1 and 2 threads means the parallel version does no
/// extra work and would scale on free cores.
double process_cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
    return s(usage.ru_utime) + s(usage.ru_stime);
}

struct Sphere {
    Point3 centre;
    float radius;
};

constexpr std::array<Sphere, 3> kSpheres{
    {{{-1.2f, 0.0f, -5.0f}, 1.0f}, {{1.2f, 0.0f, -5.0f}, 1.0f}, {{0.0f, 1.5f, -6.5f}, 1.0f}}};

float hit_sphere(const Sphere& s, const Ray& r) {
    const Vec3 oc = r.origin - s.centre;
    const float b = glm::dot(oc, r.direction), c = glm::dot(oc, oc) - s.radius * s.radius, d = b * b - c;
    if (d < 0.0f) return kInfinity;
    const float t = -b - std::sqrt(d);
    return t > 1e-4f ? t : kInfinity;
}

/// Counts the threads that traced a ray in the current render (epoch), without a lock per ray.
std::atomic<int> g_epoch{0}, g_threads_used{0};

class AnalyticScene final : public RadianceSource {
public:
    RGB radiance(const Ray& r, const SampleKey&, RayCounters& counters) const override {
        thread_local int seen_epoch = -1;
        if (const int e = g_epoch.load(std::memory_order_relaxed); seen_epoch != e) {
            seen_epoch = e;
            g_threads_used.fetch_add(1, std::memory_order_relaxed);
        }
        float best = kInfinity;
        int hit = -1;
        for (int i = 0; i < 3; ++i) {
            const float t = hit_sphere(kSpheres[static_cast<std::size_t>(i)], r);
            if (t < best) best = t, hit = i;
        }
        Vec3 n;
        RGB albedo;
        if (r.direction.y < 0.0f && (-1.0f - r.origin.y) / r.direction.y < best) {
            best = (-1.0f - r.origin.y) / r.direction.y;
            n = Vec3(0, 1, 0);
            const Point3 p = r.at(best);
            albedo = (static_cast<int>(std::floor(p.x) + std::floor(p.z)) & 1) ? RGB(0.8f) : RGB(0.2f);
        } else if (hit >= 0) {
            n = glm::normalize(r.at(best) - kSpheres[static_cast<std::size_t>(hit)].centre);
            albedo = RGB(0.9f, 0.3f + 0.3f * static_cast<float>(hit), 0.2f);
        } else {
            return RGB(0.3f, 0.5f, 0.9f);
        }
        const Vec3 to_light = glm::normalize(Vec3(2.0f, 4.0f, 1.0f));
        const Ray shadow{r.at(best) + 1e-3f * n, to_light};
        ++counters.shadow;
        for (const Sphere& s : kSpheres)
            if (hit_sphere(s, shadow) < kInfinity) return albedo * 0.05f;
        return albedo * std::max(0.0f, glm::dot(n, to_light));
    }
};

void BM_Render(benchmark::State& state, PixelPattern pattern, int spp) {
    const PinholeCamera camera(
        {.eye = {0, 0.5f, 0}, .look_at = {0, 0, -5}, .vertical_fov_degrees = 50.0f, .width = 320, .height = 240});
    const AnalyticScene scene;
    RenderSettings settings;
    settings.pattern = pattern;
    settings.spp = spp;
    settings.adaptive = {3, 0.1f};
    settings.threads = static_cast<int>(state.range(0));
    std::uint64_t rays = 0;
    const double cpu_start = process_cpu_seconds();
    int threads_used = 0;
    for (auto _ : state) {
        g_epoch.fetch_add(1);
        g_threads_used = 0;
        const RenderResult result = render(camera, scene, settings);
        rays += result.stats.rays.total();
        benchmark::DoNotOptimize(result.image.pixels().data());
        threads_used += g_threads_used.load();
    }
    state.counters["threads_used"] = static_cast<double>(threads_used) / static_cast<double>(state.iterations());
    state.counters["rays/s"] = benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
    state.counters["process_cpu_ms/render"] =
        1e3 * (process_cpu_seconds() - cpu_start) / static_cast<double>(state.iterations());
    state.counters["rays/render"] = static_cast<double>(rays) / static_cast<double>(state.iterations());
}

}  // namespace

// Real time: the work runs on TBB's threads, not the benchmark's.
BENCHMARK_CAPTURE(BM_Render, jittered_4spp, PixelPattern::jittered, 4)
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Render, adaptive_d3, PixelPattern::adaptive, 1)
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// The progressive renderer (sobol: Owen-scrambled Sobol offsets, per-pixel double sums, batched camera samples)
// on the same work as jittered_4spp: the difference is the renderer's overhead per sample.
BENCHMARK_CAPTURE(BM_Render, sobol_4spp, PixelPattern::sobol, 4)
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
