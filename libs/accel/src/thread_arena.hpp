#pragma once
/// \brief Runs a builder's parallel work on a given number of threads.
#include <tbb/task_arena.h>

#include <utility>

namespace rtlab::accel {

/// f() on `threads` threads (0: the caller's arena, whatever it has). An arena of its own only when the caller's
/// has another thread count: a nested arena's start, its worker leaving the caller's arena to join it, cost 50-85 us
/// (median, a 2-core machine) where the same parallel_for ran in 4-15 us in the caller's arena of 2 (rtlab-accel
/// --threads 2 builds in one; a kd build starts three).
template <class F>
void run_on_threads(int threads, F&& f) {
    if (threads > 0 && tbb::this_task_arena::max_concurrency() != threads)
        tbb::task_arena(threads).execute(std::forward<F>(f));
    else
        std::forward<F>(f)();
}

}  // namespace rtlab::accel
