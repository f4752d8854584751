// The scene level: when a kd-tree over the objects beats a plain list (the break-even behind
// kSceneTreeThreshold), and rays/s of whole Whitted renders at 1 and 2 threads.
//
// Break-even: N random spheres (N = 1, 2, 4, ... 256, and 12 and 24 near the break-even) in a box, radius shrinking as
// N^(-1/3) so the box stays about as full; 4096 fixed rays per query kind: closest hits of rays from a camera-like
// point through the box, and any-hit shadow segments between random points of the box. docs/data/ scene_breakeven.csv
// was made from one run of
//   rtlab_render_bench --benchmark_filter=BM_SceneQuery --benchmark_repetitions=7
//     --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
//     --benchmark_min_time=0.1 --benchmark_out_format=csv --benchmark_out=raw.csv
// keeping the medians of CPU time (the machine is shared and loaded, so wall time was up to 3x CPU time;
// the queries run on the benchmark's own thread and repetitions are interleaved in random order).
//
// Whole renders: BM_RenderScene/analytic (100 spheres, 20 quads, floor; a tenth mirror, a tenth glass; two
// point lights) and BM_RenderScene/bunny (RTLAB_SHARED_DIR/models/stanford-bunny.obj on a floor, a mirror
// sphere and a glass sphere beside it), 160 x 120, 1 spp, at 1 and 2 threads.
#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/geometry/mesh_io.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/render/render_job.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>

#include <sys/resource.h>

using namespace rtlab;

namespace {

double process_cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
    return s(usage.ru_utime) + s(usage.ru_stime);
}

std::shared_ptr<const Material> material(const std::string& name, Params p = {}) {
    static const MaterialRegistry registry = make_material_registry();
    return registry.create(name, std::move(p));
}
std::shared_ptr<const Material> lambert(float r, float g, float b) {
    Params p;
    p.set("albedo", Params::List{r, g, b});
    return material("lambert", p);
}
std::shared_ptr<const Light> point_light(const Point3& at, float intensity) {
    static const LightRegistry registry = make_light_registry();
    Params p;
    p.set("position", Params::List{at.x, at.y, at.z}).set("intensity", intensity);
    return registry.create("point", p);
}

Point3 in_box(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    return {-5.0f + 10.0f * u(rng), -5.0f + 10.0f * u(rng), -15.0f + 10.0f * u(rng)};
}

enum class Query { closest, shadow };

void BM_SceneQuery(benchmark::State& state, Query query) {
    const auto n = static_cast<int>(state.range(0));
    const bool tree = state.range(1) != 0;
    std::mt19937 rng(42);
    const auto m = lambert(0.5f, 0.5f, 0.5f);
    const float radius = 2.0f / std::cbrt(static_cast<float>(n));
    std::vector<SceneObject> objects;
    for (int i = 0; i < n; ++i) objects.push_back({std::make_shared<Sphere>(in_box(rng), radius), m, {}, ""});
    const Scene scene(std::move(objects), {tree ? std::size_t{1} : std::numeric_limits<std::size_t>::max()});
    std::vector<Ray> rays;
    for (int i = 0; i < 4096; ++i) {
        if (query == Query::closest) {
            const Point3 from(0.0f, 0.0f, 2.0f);
            rays.push_back({from, glm::normalize(in_box(rng) - from), 0.0f, kInfinity});
        } else {
            const Point3 a = in_box(rng), b = in_box(rng);
            rays.push_back({a, b - a, 0.0f, 1.0f});
        }
    }
    std::int64_t hits = 0;
    for (auto _ : state) {
        for (const Ray& r : rays) {
            if (query == Query::closest) {
                SurfaceHit h;
                hits += scene.intersect(r, h);
            } else {
                hits += scene.occluded(r);
            }
        }
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rays.size()));
    state.counters["hit_fraction"] =
        static_cast<double>(hits) / static_cast<double>(state.iterations() * static_cast<std::int64_t>(rays.size()));
    state.SetLabel(scene.structure().data());
}

void query_args(benchmark::internal::Benchmark* b) {
    for (int n : {1, 2, 4, 8, 12, 16, 24, 32, 64, 128, 256})
        for (int tree : {0, 1}) b->Args({n, tree});
}

RenderJob analytic_job() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const auto mirror = material("mirror"), glass = material("glass");
    std::vector<SceneObject> objects;
    objects.push_back({std::make_shared<Quad>(Point3(-50, 0, 20), Vec3(100, 0, 0), Vec3(0, 0, -100)),
                       lambert(0.6f, 0.6f, 0.5f),
                       {},
                       "floor"});
    auto pick = [&](int i) {
        return i % 10 == 3 ? mirror : i % 10 == 7 ? glass : lambert(0.2f + 0.8f * u(rng), 0.5f, 0.2f + 0.8f * u(rng));
    };
    for (int i = 0; i < 100; ++i) {
        const Point3 c(-5.0f + 10.0f * u(rng), 0.2f + 4.0f * u(rng), -15.0f + 10.0f * u(rng));
        objects.push_back({std::make_shared<Sphere>(c, 0.15f + 0.5f * u(rng)), pick(i), {}, ""});
    }
    for (int i = 0; i < 20; ++i) {
        const Point3 c(-5.0f + 10.0f * u(rng), 0.2f + 4.0f * u(rng), -15.0f + 10.0f * u(rng));
        const Vec3 a(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f), b(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
        objects.push_back({std::make_shared<Quad>(c, 1.5f * a, 1.5f * b), pick(i), {}, ""});
    }
    RenderJob job;
    job.scene = std::make_shared<Scene>(std::move(objects));
    job.camera = std::make_shared<PinholeCamera>(CameraSpec{
        .eye = {0, 3, 2}, .look_at = {0, 1.5f, -10}, .vertical_fov_degrees = 50.0f, .width = 160, .height = 120});
    job.lights = {point_light(Point3(-3, 8, 0), 300.0f), point_light(Point3(4, 6, -4), 100.0f)};
    job.whitted.background = RGB(0.2f, 0.3f, 0.5f);
    return job;
}

/// Null when the shared models are absent.
std::unique_ptr<RenderJob> bunny_job() {
    const char* env = std::getenv("RTLAB_SHARED_DIR");
    const std::filesystem::path file =
        std::filesystem::path(env && *env ? env : "../shared") / "models" / "stanford-bunny.obj";
    if (!std::filesystem::exists(file)) return nullptr;
    const auto shape = std::make_shared<MeshShape>(std::make_shared<const TriangleMesh>(load_mesh(file)));
    const AABB b = shape->bounds();
    const float s = b.diagonal();
    std::vector<SceneObject> objects{
        {shape, lambert(0.8f, 0.7f, 0.6f), {}, "bunny"},
        {std::make_shared<Quad>(Point3(b.lo.x - 5 * s, b.lo.y, b.hi.z + 5 * s), Vec3(10 * s, 0, 0),
                                Vec3(0, 0, -10 * s)),
         lambert(0.5f, 0.5f, 0.5f),
         {},
         "floor"},
        {std::make_shared<Sphere>(b.center() + Vec3(0.8f * s, 0, -0.3f * s), 0.3f * s),
         material("mirror"),
         {},
         "mirror"},
        {std::make_shared<Sphere>(b.center() + Vec3(-0.7f * s, -0.1f * s, 0.2f * s), 0.25f * s),
         material("glass"),
         {},
         "glass"}};
    auto job = std::make_unique<RenderJob>();
    job->scene = std::make_shared<Scene>(std::move(objects));
    job->camera = std::make_shared<PinholeCamera>(CameraSpec{.eye = b.center() + Vec3(0.2f * s, 0.4f * s, 1.6f * s),
                                                             .look_at = b.center(),
                                                             .vertical_fov_degrees = 45.0f,
                                                             .width = 160,
                                                             .height = 120});
    job->lights = {point_light(b.center() + Vec3(-s, 2 * s, s), 4.0f * s * s),
                   point_light(b.center() + Vec3(s, s, 2 * s), 2.0f * s * s)};
    job->whitted.background = RGB(0.2f, 0.3f, 0.5f);
    return job;
}

void BM_RenderScene(benchmark::State& state, bool bunny) {
    static const RenderJob analytic = analytic_job();
    static const std::unique_ptr<RenderJob> bunny_scene = bunny_job();
    if (bunny && !bunny_scene) {
        state.SkipWithError("RTLAB_SHARED_DIR/models/stanford-bunny.obj not found");
        return;
    }
    RenderJob job = bunny ? *bunny_scene : analytic;
    job.settings.threads = static_cast<int>(state.range(0));
    std::uint64_t rays = 0;
    const double cpu_start = process_cpu_seconds();
    for (auto _ : state) {
        const RenderResult result = render_job(job);
        rays += result.stats.rays.total();
        benchmark::DoNotOptimize(result.image.pixels().data());
    }
    state.counters["rays/s"] = benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
    state.counters["cpu_ms/render"] =
        1e3 * (process_cpu_seconds() - cpu_start) / static_cast<double>(state.iterations());
    state.counters["rays/render"] = static_cast<double>(rays) / static_cast<double>(state.iterations());
    state.SetLabel(job.scene->structure().data());
}

}  // namespace

BENCHMARK_CAPTURE(BM_SceneQuery, closest, Query::closest)->Apply(query_args);
BENCHMARK_CAPTURE(BM_SceneQuery, shadow, Query::shadow)->Apply(query_args);
// Real time: the work runs on TBB's threads, not the benchmark's.
BENCHMARK_CAPTURE(BM_RenderScene, analytic, false)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RenderScene, bunny, true)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
