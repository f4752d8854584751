// ns per BRDF evaluation (through the Brdf interface, as the shading code calls it) and per Fresnel term:
// exact dielectric against Schlick's approximation, and the exact conductor. Each iteration evaluates a
// batch of precomputed random direction pairs (or cosines), so the loop overhead is spread over kBatch
// evaluations; the "per_eval" counter is the time per single evaluation.
// Run: build/<preset>/bin/rtlab_shading_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// (medians are the figures to quote).
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/brdf.hpp>
#include <rtlab/shading/optics.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

using namespace rtlab;

namespace {
constexpr int kBatch = 4096;

struct Pair {
    Vec3 wo, wi;
};

Vec3 uniform_hemisphere(Rng& rng) {
    const float z = rng.uniform();
    const float phi = 2.0f * kPi * rng.uniform();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

const std::vector<Pair>& pairs() {
    static const std::vector<Pair> out = [] {
        Rng rng(42);
        std::vector<Pair> p(kBatch);
        for (Pair& q : p) q = {uniform_hemisphere(rng), uniform_hemisphere(rng)};
        return p;
    }();
    return out;
}

const std::vector<float>& cosines() {
    static const std::vector<float> out = [] {
        Rng rng(43);
        std::vector<float> c(kBatch);
        for (float& x : c) x = rng.uniform();
        return c;
    }();
    return out;
}

void per_eval(benchmark::State& state) {
    state.counters["per_eval"] = benchmark::Counter(static_cast<double>(state.iterations()) * kBatch,
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void run_brdf(benchmark::State& state, const Brdf& brdf) {
    // Hidden from the optimiser, so that every call goes through the vtable as in the shading code.
    const Brdf* f = &brdf;
    benchmark::DoNotOptimize(f);
    const auto& p = pairs();
    for (auto _ : state)
        for (const Pair& q : p) benchmark::DoNotOptimize(f->eval(q.wo, q.wi));
    per_eval(state);
}

template <class F>
void run_cosines(benchmark::State& state, F&& f) {
    const auto& c = cosines();
    for (auto _ : state)
        for (float x : c) benchmark::DoNotOptimize(f(x));
    per_eval(state);
}

using MD = MicrofacetDistribution;

void BM_lambert(benchmark::State& state) { run_brdf(state, LambertBrdf(RGB(0.8f))); }
void BM_phong(benchmark::State& state) { run_brdf(state, PhongBrdf(RGB(0.3f), RGB(0.6f), 40.0f)); }
void BM_blinn_phong(benchmark::State& state) { run_brdf(state, BlinnPhongBrdf(RGB(0.3f), RGB(0.6f), 40.0f)); }
void BM_cook_torrance_ggx_dielectric(benchmark::State& state) {
    run_brdf(state, CookTorranceBrdf(RGB(0.5f), RGB(1.0f), MD::from_roughness(MicrofacetModel::ggx, 0.4f),
                                     Fresnel::dielectric(1.5f)));
}
void BM_cook_torrance_ggx_conductor(benchmark::State& state) {
    run_brdf(state, CookTorranceBrdf(RGB(0.0f), RGB(1.0f), MD::from_roughness(MicrofacetModel::ggx, 0.4f),
                                     Fresnel::conductor(kGold)));
}
void BM_cook_torrance_beckmann_dielectric(benchmark::State& state) {
    run_brdf(state, CookTorranceBrdf(RGB(0.5f), RGB(1.0f), MD::from_roughness(MicrofacetModel::beckmann, 0.4f),
                                     Fresnel::dielectric(1.5f)));
}
void BM_cook_torrance_beckmann_conductor(benchmark::State& state) {
    run_brdf(state, CookTorranceBrdf(RGB(0.0f), RGB(1.0f), MD::from_roughness(MicrofacetModel::beckmann, 0.4f),
                                     Fresnel::conductor(kGold)));
}
void BM_ashikhmin_shirley(benchmark::State& state) {
    run_brdf(state, AshikhminShirleyBrdf(RGB(0.5f), RGB(0.3f), 10.0f, 1000.0f));
}

void BM_fresnel_dielectric(benchmark::State& state) {
    run_cosines(state, [](float c) { return fresnel_dielectric(c, 1.0f / 1.5f); });
}
void BM_fresnel_schlick(benchmark::State& state) {
    run_cosines(state, [](float c) { return fresnel_schlick(c, 1.0f / 1.5f); });
}
void BM_fresnel_conductor(benchmark::State& state) {
    run_cosines(state, [](float c) { return fresnel_conductor(c, kGold.eta.g, kGold.k.g); });
}
void BM_fresnel_conductor_rgb(benchmark::State& state) {
    run_cosines(state, [](float c) { return fresnel_conductor(c, kGold); });
}
}  // namespace

BENCHMARK(BM_lambert);
BENCHMARK(BM_phong);
BENCHMARK(BM_blinn_phong);
BENCHMARK(BM_cook_torrance_ggx_dielectric);
BENCHMARK(BM_cook_torrance_ggx_conductor);
BENCHMARK(BM_cook_torrance_beckmann_dielectric);
BENCHMARK(BM_cook_torrance_beckmann_conductor);
BENCHMARK(BM_ashikhmin_shirley);
BENCHMARK(BM_fresnel_dielectric);
BENCHMARK(BM_fresnel_schlick);
BENCHMARK(BM_fresnel_conductor);
BENCHMARK(BM_fresnel_conductor_rgb);
