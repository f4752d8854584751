#include "timing.hpp"

#include <fmt/core.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <ctime>

namespace rtlab::accel_app {

namespace {

// One pass: every ray traced, each answer written to its record, in parallel blocks.
void trace_closest(const TriangleAccelerator& accel, const std::vector<Ray>& rays, std::vector<MeshHit>& out) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) {
                              MeshHit h;
                              out[i] = accel.intersect(rays[i], h) ? h : MeshHit{};
                          }
                      });
}

void trace_any(const TriangleAccelerator& accel, const std::vector<Ray>& rays, std::vector<unsigned char>& out) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) out[i] = accel.occluded(rays[i]) ? 1 : 0;
                      });
}

}  // namespace

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double clock_seconds(bool thread_time) {
    if (thread_time) {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }
    return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<Built> build_methods(const std::vector<std::string>& methods, const TriangleMesh& mesh,
                                 const BuildOptions& options, int runs, tbb::task_arena& arena) {
    std::vector<Built> built(methods.size());
    std::vector<std::vector<double>> build_times(methods.size());
    // The methods take turns, as in trace_in_rounds: the build-time ratios of one run then hold on a busy
    // machine. Brute force and the naive SAH are built once (their builds are trivial or very slow).
    for (int round = 0; round < runs; ++round) {
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const bool once = methods[m] == "brute" || methods[m] == "kd-sah-naive";
            if (once && round > 0) continue;
            built[m].method = methods[m];
            built[m].accel.reset();  // the previous round's structure goes before the next is built
            const auto start = Clock::now();
            arena.execute([&] { built[m].accel = make_accelerator(methods[m], mesh, options); });
            build_times[m].push_back(seconds_since(start));
        }
    }
    for (std::size_t m = 0; m < methods.size(); ++m) {
        built[m].build_s = median(build_times[m]);
        for (const std::string& warning : built[m].accel->stats().warnings)
            fmt::print(stderr, "warning: {}: {}\n", methods[m], warning);
    }
    return built;
}

// The methods take turns within each round: a slow spell of these shared machines then falls on all of them
// alike, and the ratios between methods of one run hold even when the absolute figures drift.
std::vector<Traced> trace_in_rounds(const std::vector<Built>& built, const std::vector<Ray>& rays,
                                    const std::vector<Ray>& sampled, int runs, tbb::task_arena& arena) {
    std::vector<Traced> traced(built.size());
    for (std::size_t m = 0; m < built.size(); ++m) {
        // Brute force traces only the reference sample: a full pass would take hours.
        traced[m].rays = built[m].method == "brute" ? &sampled : &rays;
        traced[m].hits.resize(traced[m].rays->size());
        traced[m].blocked.resize(traced[m].rays->size());
    }
    // One thread: its CPU time, which other processes on these shared machines disturb less than wall time (two
    // kd-sah walks against each other read 0.96-1.03 in wall time on a quiet machine, and moved by 10% between
    // runs when another build ran).
    const bool thread_time = arena.max_concurrency() == 1;
    arena.execute([&] {
        for (int round = -1; round < runs; ++round) {  // round -1: the untimed warm-up
            for (std::size_t m = 0; m < built.size(); ++m) {
                Traced& t = traced[m];
                const double start = clock_seconds(thread_time);
                trace_closest(*built[m].accel, *t.rays, t.hits);
                const double middle = clock_seconds(thread_time);
                trace_any(*built[m].accel, *t.rays, t.blocked);
                const double end = clock_seconds(thread_time);
                if (round < 0) continue;
                t.closest_s.push_back(middle - start);
                t.any_s.push_back(end - middle);
            }
        }
    });
    return traced;
}

}  // namespace rtlab::accel_app
