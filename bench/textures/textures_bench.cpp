// ns per texture lookup: improved Perlin noise (2D, 3D, fBm with 6 octaves), simplex noise, and the
// bilinear image and cube-map lookups. Each benchmark iteration evaluates a batch of precomputed
// points, so the loop overhead is spread over kBatch lookups; the "per_lookup" counter is the time
// per single lookup. Run: build/<preset>/bin/rtlab_textures_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true (medians are the figures to quote).
#include <rtlab/core/rng.hpp>
#include <rtlab/textures/cube_map.hpp>
#include <rtlab/textures/fractal_noise.hpp>
#include <rtlab/textures/image_texture.hpp>
#include <rtlab/textures/perlin_noise.hpp>
#include <rtlab/textures/simplex_noise.hpp>

#include <benchmark/benchmark.h>

#include <vector>

using namespace rtlab;

namespace {
constexpr int kBatch = 4096;

std::vector<Vec3> points(float extent) {
    Rng rng(42);
    std::vector<Vec3> out(kBatch);
    for (Vec3& p : out) p = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * (2.0f * extent) - extent;
    return out;
}

void per_lookup(benchmark::State& state) {
    state.counters["per_lookup"] = benchmark::Counter(static_cast<double>(state.iterations()) * kBatch,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_perlin_2d(benchmark::State& state) {
    const PerlinNoise noise;
    const auto pts = points(100.0f);
    for (auto _ : state)
        for (const Vec3& p : pts) benchmark::DoNotOptimize(noise.eval(p.x, p.y));
    per_lookup(state);
}

void BM_perlin_3d(benchmark::State& state) {
    const PerlinNoise noise;
    const auto pts = points(100.0f);
    for (auto _ : state)
        for (const Vec3& p : pts) benchmark::DoNotOptimize(noise.eval(p.x, p.y, p.z));
    per_lookup(state);
}

void BM_perlin_fbm6_3d(benchmark::State& state) {
    const PerlinNoise noise;
    const FractalParams f{6, 2.0, 0.5f};
    const auto pts = points(100.0f);
    for (auto _ : state)
        for (const Vec3& p : pts) benchmark::DoNotOptimize(fbm(noise, p.x, p.y, p.z, f));
    per_lookup(state);
}

void BM_perlin_fbm6_2d(benchmark::State& state) {
    const PerlinNoise noise;
    const FractalParams f{6, 2.0, 0.5f};
    const auto pts = points(100.0f);
    for (auto _ : state)
        for (const Vec3& p : pts) benchmark::DoNotOptimize(fbm(noise, p.x, p.y, f));
    per_lookup(state);
}

void BM_simplex_2d(benchmark::State& state) {
    const SimplexNoise noise;
    const auto pts = points(100.0f);
    for (auto _ : state)
        for (const Vec3& p : pts) benchmark::DoNotOptimize(noise.eval(p.x, p.y));
    per_lookup(state);
}

void BM_simplex_3d(benchmark::State& state) {
    const SimplexNoise noise;
    const auto pts = points(100.0f);
    for (auto _ : state)
        for (const Vec3& p : pts) benchmark::DoNotOptimize(noise.eval(p.x, p.y, p.z));
    per_lookup(state);
}

// A 1024 x 1024 image (12 MiB of float RGB, larger than the caches) at random uv: the cache-missing case.
// range(0) = 1 looks up a coherent sweep instead (neighbouring pixels in a row), the renderer's usual case.
void BM_image_bilinear(benchmark::State& state) {
    auto img = std::make_shared<Image>(1024, 1024);
    Rng rng(1);
    for (RGB& p : img->pixels()) p = RGB(rng.uniform(), rng.uniform(), rng.uniform());
    const ImageTexture tex(img, {.wrap = WrapMode::repeat});
    std::vector<Vec2> uvs(kBatch);
    if (state.range(0) == 0) {
        for (Vec2& uv : uvs) uv = rng.uniform2() * 3.0f - 1.0f;
    } else {
        for (int k = 0; k < kBatch; ++k) uvs[k] = Vec2(static_cast<float>(k) / kBatch * 4.0f, 0.37f);
    }
    for (auto _ : state)
        for (const Vec2& uv : uvs) benchmark::DoNotOptimize(tex.sample(uv));
    per_lookup(state);
}

void BM_cubemap_bilinear(benchmark::State& state) {
    std::array<Image, 6> faces;
    Rng rng(2);
    for (Image& f : faces) {
        f = Image(256, 256);
        for (RGB& p : f.pixels()) p = RGB(rng.uniform(), rng.uniform(), rng.uniform());
    }
    const CubeMapTexture map(std::move(faces));
    const auto dirs = points(1.0f);
    for (auto _ : state)
        for (const Vec3& d : dirs) benchmark::DoNotOptimize(map.sample(d));
    per_lookup(state);
}
}  // namespace

BENCHMARK(BM_perlin_2d);
BENCHMARK(BM_perlin_3d);
BENCHMARK(BM_perlin_fbm6_2d);
BENCHMARK(BM_perlin_fbm6_3d);
BENCHMARK(BM_simplex_2d);
BENCHMARK(BM_simplex_3d);
BENCHMARK(BM_image_bilinear)->Arg(0)->Arg(1)->ArgName("coherent");
BENCHMARK(BM_cubemap_bilinear);
