#pragma once
// Building every method and tracing a ray set with all of them in timed rounds.
#include <rtlab/accel/accelerator.hpp>

#include <tbb/task_arena.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace rtlab::accel_app {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start);
/// Seconds on a clock: with thread_time, the CPU time of the calling thread -- with one thread it runs all of an
/// arena's work, and time the scheduler gives to other processes of a shared machine is then not counted -- and
/// wall time otherwise.
double clock_seconds(bool thread_time);
double median(std::vector<double> v);

/// A method built for the run.
struct Built {
    std::string method;
    std::unique_ptr<TriangleAccelerator> accel;
    double build_s = 0;  // median of the timed builds
};

/// What tracing one ray set with one method gave.
struct Traced {
    const std::vector<Ray>* rays = nullptr;  // the set's rays, or only the sample for brute force
    std::vector<MeshHit> hits;
    std::vector<unsigned char> blocked;
    std::vector<double> closest_s, any_s;  // one per timed round
};

/// Builds every method in the arena, each `runs` times (once for the slow builders), keeping the last build.
std::vector<Built> build_methods(const std::vector<std::string>& methods, const TriangleMesh& mesh,
                                 const BuildOptions& options, int runs, tbb::task_arena& arena);

/// Traces the set with every method: one untimed round, then `runs` rounds each timing one closest-hit and
/// one any-hit pass of every method in turn (in the tracing thread's CPU time for an arena of one thread, in
/// wall time otherwise). Brute force traces only `sampled`.
std::vector<Traced> trace_in_rounds(const std::vector<Built>& built, const std::vector<Ray>& rays,
                                    const std::vector<Ray>& sampled, int runs, tbb::task_arena& arena);

}  // namespace rtlab::accel_app
