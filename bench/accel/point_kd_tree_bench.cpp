// PointKdTree: build time, and k-nearest (k = 50) and radius search times per query, on uniform points in
// the unit cube and on 20 Gaussian clusters (a photon map's clumps); brute force for small n as the baseline.
// Arguments: point count, then 0 = uniform, 1 = clustered (and for build, the thread count, 0 = all).
#include <rtlab/accel/point_kd_tree.hpp>
#include <rtlab/core/rng.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace {

using namespace rtlab;

constexpr std::size_t kK = 50;

Point3 uniform_point(Rng& rng) {
    const float x = rng.uniform();
    const float y = rng.uniform();
    return {x, y, rng.uniform()};
}

Vec3 gaussian3(Rng& rng) {
    Vec3 v;
    for (int a = 0; a < 3; ++a)
        v[a] = std::sqrt(-2.0f * std::log(1.0f - rng.uniform())) * std::cos(2.0f * kPi * rng.uniform());
    return v;
}

const std::vector<Point3>& points(std::size_t n, bool clustered) {
    static std::map<std::pair<std::size_t, bool>, std::vector<Point3>> cache;
    std::vector<Point3>& p = cache[{n, clustered}];
    if (p.empty()) {
        Rng rng(n, clustered ? 1 : 0);
        std::vector<Point3> centres(20);
        for (Point3& c : centres) c = uniform_point(rng);
        for (std::size_t i = 0; i < n; ++i)
            p.push_back(clustered ? centres[rng.uniform_u32(20)] + 0.03f * gaussian3(rng) : uniform_point(rng));
    }
    return p;
}

// Queries where a renderer would ask: among the points (a point's position, jittered a little).
std::vector<Point3> queries(const std::vector<Point3>& pts) {
    Rng rng(7, 7);
    std::vector<Point3> q(4096);
    for (Point3& x : q) x = pts[rng.uniform_u32(static_cast<std::uint32_t>(pts.size()))] + 0.002f * gaussian3(rng);
    return q;
}

void build(benchmark::State& state) {
    const auto& pts = points(static_cast<std::size_t>(state.range(0)), state.range(1) != 0);
    for (auto _ : state) benchmark::DoNotOptimize(PointKdTree(pts, static_cast<int>(state.range(2))));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}

void nearest(benchmark::State& state) {
    const auto& pts = points(static_cast<std::size_t>(state.range(0)), state.range(1) != 0);
    const PointKdTree tree(pts);
    const std::vector<Point3> q = queries(pts);
    PointNeighbor out[kK];
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(tree.nearest(q[i++ & (q.size() - 1)], kInfinity, out));
        benchmark::DoNotOptimize(out);
    }
}

// The same answer as nearest, by a scan of every point and a selection of the k best.
void nearest_brute_force(benchmark::State& state) {
    const auto& pts = points(static_cast<std::size_t>(state.range(0)), state.range(1) != 0);
    const std::vector<Point3> q = queries(pts);
    std::vector<PointNeighbor> all(pts.size());
    const auto before = [](const PointNeighbor& a, const PointNeighbor& b) {
        return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
    };
    std::size_t i = 0;
    for (auto _ : state) {
        const Point3& x = q[i++ & (q.size() - 1)];
        for (std::size_t j = 0; j < pts.size(); ++j)
            all[j] = {static_cast<std::uint32_t>(j), squared_distance(x, pts[j])};
        const auto k = static_cast<std::ptrdiff_t>(std::min(kK, all.size()));
        std::partial_sort(all.begin(), all.begin() + k, all.end(), before);
        benchmark::DoNotOptimize(all.data());
    }
}

// All points within the radius that holds about k = 50 of them in the uniform cloud.
void within(benchmark::State& state) {
    const auto& pts = points(static_cast<std::size_t>(state.range(0)), state.range(1) != 0);
    const PointKdTree tree(pts);
    const std::vector<Point3> q = queries(pts);
    const float radius = std::cbrt(static_cast<float>(kK) / (static_cast<float>(pts.size()) * 4.0f / 3.0f * kPi));
    std::size_t i = 0;
    std::size_t found = 0;
    for (auto _ : state)
        tree.for_each_within(q[i++ & (q.size() - 1)], radius * radius, [&](std::uint32_t, float) { ++found; });
    state.counters["found"] = benchmark::Counter(static_cast<double>(found) / static_cast<double>(state.iterations()));
}

}  // namespace

BENCHMARK(build)->ArgsProduct({{100000, 1000000}, {0, 1}, {1, 0}})->Unit(benchmark::kMillisecond);
BENCHMARK(nearest)->ArgsProduct({{1000, 10000, 100000, 1000000}, {0, 1}});
BENCHMARK(nearest_brute_force)->ArgsProduct({{1000, 10000}, {0, 1}});
BENCHMARK(within)->ArgsProduct({{100000, 1000000}, {0, 1}});
