// Shading costs: ns to shade one hit per material (terms looked up, one point light evaluated), ns for a
// whole primary hit (closest hit on a sphere, shading, one shadow ray; no secondary rays), and ns for one
// shadow ray through 0, 1 and 8 transparent surfaces. Each iteration runs a batch of kBatch precomputed
// cases; "per_item" is the time per case. Run: build/release/bin/rtlab_shading_bench
//   --benchmark_repetitions=5 --benchmark_report_aggregates_only=true (quote the medians).
#include <rtlab/core/rng.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/shading/whitted.hpp>

#include <benchmark/benchmark.h>

#include <iterator>
#include <string>
#include <vector>

using namespace rtlab;

namespace {
constexpr int kBatch = 1024;

void per_item(benchmark::State& state) {
    state.counters["per_item"] = benchmark::Counter(static_cast<double>(state.iterations()) * kBatch,
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

const char* const kMaterials[] = {"lambert",           "phong",  "blinn-phong", "cook-torrance",
                                  "ashikhmin-shirley", "mirror", "glass"};
constexpr int kLastMaterial = static_cast<int>(std::size(kMaterials)) - 1;

std::shared_ptr<const Light> point_light(const Point3& at, float intensity) {
    Params p;
    p.set("position", Params::List{at.x, at.y, at.z}).set("intensity", intensity);
    return make_light_registry().create("point", p);
}

Vec3 upper_hemisphere(Rng& rng) {
    Vec3 v;
    do v = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 2.0f - 1.0f;
    while (glm::dot(v, v) > 1.0f || glm::dot(v, v) < 1e-4f);
    v = glm::normalize(v);
    return v.z < 0.0f ? Vec3(v.x, v.y, -v.z) : v;
}

// Material::terms and direct() for one light, both conventions alternating: the material's own cost.
void BM_material_shade(benchmark::State& state) {
    const auto material = make_material_registry().create(kMaterials[state.range(0)], {});
    Rng rng(5);
    std::vector<std::pair<Vec3, Vec3>> dirs(kBatch);
    for (auto& [wo, wi] : dirs) wo = upper_hemisphere(rng), wi = upper_hemisphere(rng);
    TextureLookup q;
    for (auto _ : state) {
        for (int i = 0; i < kBatch; ++i) {
            q.uv.x = static_cast<float>(i) * (1.0f / kBatch);
            const SurfaceTerms t = material->terms(q);
            benchmark::DoNotOptimize(material->direct(t, dirs[i].first, dirs[i].second,
                                                      (i & 1) ? Convention::classic : Convention::physical));
        }
    }
    state.SetLabel(kMaterials[state.range(0)]);
    per_item(state);
}
BENCHMARK(BM_material_shade)->DenseRange(0, kLastMaterial);

// radiance() of a primary ray hitting a sphere on a floor: closest hit over 2 shapes, the material, one
// point light with its shadow ray; max_depth 0, so mirror and glass stop at their own hit.
void BM_primary_hit(benchmark::State& state) {
    ShapeList scene;
    const auto material = make_material_registry().create(kMaterials[state.range(0)], {});
    scene.add(std::make_shared<Sphere>(Point3(0.0f), 1.0f), material);
    scene.add(std::make_shared<Quad>(Point3(-10, -1, -10), Vec3(0, 0, 20), Vec3(20, 0, 0)),
              make_material_registry().create("lambert", {}));
    WhittedOptions options;
    options.max_depth = 0;
    const WhittedIntegrator w(scene, {point_light(Point3(2, 4, 3), 20.0f)}, options);
    Rng rng(9);
    std::vector<Ray> rays(kBatch);
    for (Ray& r : rays) {
        r.origin = Point3(0.0f, 0.0f, 5.0f);
        r.direction = Vec3(rng.uniform() * 1.2f - 0.6f, rng.uniform() * 1.2f - 0.6f, 0.0f) - r.origin;
    }
    RayStats stats;
    for (auto _ : state)
        for (const Ray& r : rays) benchmark::DoNotOptimize(w.radiance(r, {}, stats));
    state.SetLabel(kMaterials[state.range(0)]);
    per_item(state);
}
BENCHMARK(BM_primary_hit)->DenseRange(0, kLastMaterial);

// One shadow ray from a floor point to a point light through N panes of kt 0.9 (and no opaque caster):
// the any-hit query, then N + 1 transmissive closest-hit queries.
void BM_shadow_ray(benchmark::State& state) {
    const int panes = static_cast<int>(state.range(0));
    Params pane;
    pane.set("kt", 0.9).set("albedo", 0.0);
    const auto glass = make_material_registry().create("lambert", pane);
    ShapeList scene;
    scene.add(std::make_shared<Quad>(Point3(-10, 0, -10), Vec3(0, 0, 20), Vec3(20, 0, 0)),
              make_material_registry().create("lambert", {}));
    for (int i = 0; i < panes; ++i) {
        const float y = 1.0f + static_cast<float>(i);
        scene.add(std::make_shared<Quad>(Point3(-10, y, -10), Vec3(0, 0, 20), Vec3(20, 0, 0)), glass);
    }
    const WhittedIntegrator w(scene, {});
    Rng rng(13);
    std::vector<SurfaceHit> hits(kBatch);
    for (SurfaceHit& h : hits) {
        const Ray down{Point3(rng.uniform() * 4.0f - 2.0f, 0.5f, rng.uniform() * 4.0f - 2.0f), Vec3(0, -1, 0)};
        scene.intersect(down, h);
    }
    LightSample light;
    light.position = Point3(0.0f, 20.0f, 0.0f);
    RayStats stats;
    for (auto _ : state)
        for (const SurfaceHit& h : hits) {
            light.wi = glm::normalize(light.position - h.point);
            benchmark::DoNotOptimize(w.transmittance(h, light, stats));
        }
    per_item(state);
}
BENCHMARK(BM_shadow_ray)->Arg(0)->Arg(1)->Arg(8);

}  // namespace
