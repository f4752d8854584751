#include "tile_parallel.hpp"

#include <rtlab/core/error.hpp>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace rtlab::detail {

namespace {

/// One arena per thread count, kept for the process. A task_arena made afresh for every render gets
/// TBB's worker threads for its first render only: later ones ran on the calling thread alone (measured
/// on oneTBB 2021.8, 2 cores: 1 thread busy of 2 in every render after the first).
tbb::task_arena& arena_for(int threads) {
    static std::mutex mutex;
    static std::map<int, std::unique_ptr<tbb::task_arena>> arenas;
    std::lock_guard lock(mutex);
    std::unique_ptr<tbb::task_arena>& arena = arenas[threads];
    if (!arena) arena = std::make_unique<tbb::task_arena>(threads);
    return *arena;
}

}  // namespace

void check_tile_settings(const char* who, const Camera& camera, int tile_size, int threads) {
    const std::string prefix(who);
    if (camera.width() <= 0 || camera.height() <= 0)
        throw Error(prefix + ": image size must be positive, got " + std::to_string(camera.width()) + "x" +
                    std::to_string(camera.height()));
    if (tile_size < 0)
        throw Error(prefix + ": tile size must be at least 1 (or 0: from the image size), got " +
                    std::to_string(tile_size));
    if (threads < 0) throw Error(prefix + ": thread count must be >= 0, got " + std::to_string(threads));
}

void run_on_threads(int threads, const std::function<void()>& run) {
    if (threads > 0) {
        // More threads than cores (a determinism test asks for 8 on 2 cores) need TBB's global limit
        // raised as well as an arena that large; the limit is restored when the render returns.
        std::optional<tbb::global_control> allow;
        if (threads > tbb::this_task_arena::max_concurrency())
            allow.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
        arena_for(threads).execute(run);
    } else {
        run();
    }
}

void for_each_tile(int threads, int tiles, const std::function<void(int)>& render_tile) {
    auto run = [&] {
        // One tile per task: tiles are costly and uneven, and the image does not depend on the split.
        tbb::parallel_for(
            tbb::blocked_range<int>(0, tiles, 1),
            [&](const tbb::blocked_range<int>& r) {
                for (int i = r.begin(); i != r.end(); ++i) render_tile(i);
            },
            tbb::simple_partitioner());
    };
    run_on_threads(threads, run);
}

}  // namespace rtlab::detail
