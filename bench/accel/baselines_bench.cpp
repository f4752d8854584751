// Closest-hit and any-hit ns per ray for kd-sah and the baseline structures (bvh, octree, embree) on a closed
// icosphere of 81,920 triangles and the standard random ray set of FORMATS.md (fewer rays); build time
// per method. Whole-model figures come from rtlab-accel, this tracks the inner loops between commits.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/ray_io.hpp>

#include <benchmark/benchmark.h>

#include "test_meshes.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace {

using namespace rtlab;

const TriangleMesh& mesh() {
    static const TriangleMesh m = test::icosphere(6);
    return m;
}

const std::vector<Ray>& rays() {
    static const std::vector<Ray> r = random_rays(mesh().bounds(), 1u << 14);
    return r;
}

bool available(const std::string& method) {
    const auto all = accelerator_methods();
    return std::find(all.begin(), all.end(), method) != all.end();
}

void closest_hit(benchmark::State& state, const std::string& method) {
    if (!available(method)) return state.SkipWithError("method not built");
    const auto accel = make_accelerator(method, mesh());
    std::size_t i = 0;
    for (auto _ : state) {
        MeshHit hit;
        benchmark::DoNotOptimize(accel->intersect(rays()[i++ & (rays().size() - 1)], hit));
        benchmark::DoNotOptimize(hit);
    }
}

void any_hit(benchmark::State& state, const std::string& method) {
    if (!available(method)) return state.SkipWithError("method not built");
    const auto accel = make_accelerator(method, mesh());
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(accel->occluded(rays()[i++ & (rays().size() - 1)]));
}

void build(benchmark::State& state, const std::string& method) {
    if (!available(method)) return state.SkipWithError("method not built");
    for (auto _ : state) benchmark::DoNotOptimize(make_accelerator(method, mesh()));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh().triangle_count()));
}

}  // namespace

BENCHMARK_CAPTURE(closest_hit, kd_sah, std::string("kd-sah"));
BENCHMARK_CAPTURE(closest_hit, bvh, std::string("bvh"));
BENCHMARK_CAPTURE(closest_hit, octree, std::string("octree"));
BENCHMARK_CAPTURE(closest_hit, embree, std::string("embree"));
BENCHMARK_CAPTURE(any_hit, kd_sah, std::string("kd-sah"));
BENCHMARK_CAPTURE(any_hit, bvh, std::string("bvh"));
BENCHMARK_CAPTURE(any_hit, octree, std::string("octree"));
BENCHMARK_CAPTURE(any_hit, embree, std::string("embree"));
BENCHMARK_CAPTURE(build, kd_sah, std::string("kd-sah"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(build, bvh, std::string("bvh"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(build, octree, std::string("octree"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(build, embree, std::string("embree"))->Unit(benchmark::kMillisecond);
