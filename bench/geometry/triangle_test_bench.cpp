// ns per ray-triangle test for the three methods, on the same rays and triangles: 4096 random triangles
// in the unit cube and rays from a sphere around it aimed at random points of the triangles (so about
// half the tests hit, half miss near an edge), tested pairwise in a fixed order.
#include <rtlab/geometry/triangle_intersect.hpp>

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

namespace {

using namespace rtlab;

struct Workload {
    std::vector<Point3> corners;  // 3 per triangle
    std::vector<PlaneTriangle> planes;
    std::vector<Ray> rays;  // ray i is tested against triangle i
};

const Workload& workload() {
    static const Workload w = [] {
        Workload w;
        std::mt19937 rng(42);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        constexpr int n = 4096;
        for (int i = 0; i < n; ++i) {
            const Point3 base(u(rng), u(rng), u(rng));
            Point3 c[3];
            for (auto& p : c) p = base + 0.2f * Vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
            w.corners.insert(w.corners.end(), {c[0], c[1], c[2]});
            w.planes.emplace_back(c[0], c[1], c[2]);
            // Aim at barycentrics in [-0.2, 1.2]: some inside, some just outside.
            float a = 1.4f * u(rng) - 0.2f, b = 1.4f * u(rng) - 0.2f;
            const Point3 target = (1 - a - b) * c[0] + a * c[1] + b * c[2];
            const float z = 2 * u(rng) - 1, phi = 6.2831853f * u(rng), r = std::sqrt(std::max(0.0f, 1 - z * z));
            const Point3 origin = Point3(0.5f) + 3.0f * Vec3(r * std::cos(phi), r * std::sin(phi), z);
            w.rays.push_back(Ray{origin, glm::normalize(target - origin)});
        }
        return w;
    }();
    return w;
}

void bm_watertight(benchmark::State& state) {
    const Workload& w = workload();
    std::vector<WatertightRay> sheared;
    for (const Ray& r : w.rays) sheared.emplace_back(r);
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        const auto h = intersect_watertight(sheared[i], 0.0f, kInfinity, w.corners[3 * i], w.corners[3 * i + 1],
                                            w.corners[3 * i + 2]);
        hits += h.has_value();
        benchmark::DoNotOptimize(h);
        i = (i + 1) & 4095;
    }
    state.counters["hit_rate"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}

// The same, with the per-ray shear computed inside the loop: what a single query costs.
void bm_watertight_with_setup(benchmark::State& state) {
    const Workload& w = workload();
    std::size_t i = 0;
    for (auto _ : state) {
        const auto h = intersect_watertight(WatertightRay(w.rays[i]), 0.0f, kInfinity, w.corners[3 * i],
                                            w.corners[3 * i + 1], w.corners[3 * i + 2]);
        benchmark::DoNotOptimize(h);
        i = (i + 1) & 4095;
    }
}

void bm_moller(benchmark::State& state) {
    const Workload& w = workload();
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        const auto h =
            intersect_moller(w.rays[i], 0.0f, kInfinity, w.corners[3 * i], w.corners[3 * i + 1], w.corners[3 * i + 2]);
        hits += h.has_value();
        benchmark::DoNotOptimize(h);
        i = (i + 1) & 4095;
    }
    state.counters["hit_rate"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}

void bm_plane(benchmark::State& state) {
    const Workload& w = workload();
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        const auto h = intersect_plane(w.rays[i], 0.0f, kInfinity, w.planes[i]);
        hits += h.has_value();
        benchmark::DoNotOptimize(h);
        i = (i + 1) & 4095;
    }
    state.counters["hit_rate"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}

}  // namespace

BENCHMARK(bm_watertight);
BENCHMARK(bm_watertight_with_setup);
BENCHMARK(bm_moller);
BENCHMARK(bm_plane);
