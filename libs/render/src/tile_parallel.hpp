#pragma once
/// \brief What the tile renderers share: tiles, the stop flag, and running tiles in parallel on a thread count.
#include <rtlab/render/renderer.hpp>

#include <functional>

namespace rtlab::detail {

/// Pixels x0 <= x < x1, y0 <= y < y1.
struct Tile {
    int x0, y0, x1, y1;
};

/// The image cut into tile_size x tile_size tiles (smaller at the right and bottom), row-major.
struct TileGrid {
    int width, height, tile_size, tiles_x, tiles_y;

    TileGrid(int w, int h, int ts)
        : width(w), height(h), tile_size(ts), tiles_x((w + ts - 1) / ts), tiles_y((h + ts - 1) / ts) {}
    int count() const { return tiles_x * tiles_y; }
    Tile tile(int index) const {
        const int tx = index % tiles_x, ty = index / tiles_x;
        return {tx * tile_size, ty * tile_size, std::min(width, (tx + 1) * tile_size),
                std::min(height, (ty + 1) * tile_size)};
    }
};

inline bool stopped(const RenderCallbacks& cb) {
    if (cb.stop && cb.stop->load(std::memory_order_relaxed)) return true;
    return cb.deadline != std::chrono::steady_clock::time_point::max() &&
           std::chrono::steady_clock::now() >= cb.deadline;
}

/// Throws rtlab::Error, prefixed by `who`, for a non-positive image size, a negative tile size or thread count.
void check_tile_settings(const char* who, const Camera& camera, int tile_size, int threads);

/// Runs `run` in the process's arena of `threads` threads (0: TBB's default), so that the parallel algorithms it
/// calls use that many.
void run_on_threads(int threads, const std::function<void()>& run);

/// Calls render_tile(i) for every i in [0, tiles), one tile per task, on `threads` threads (0: TBB's default).
void for_each_tile(int threads, int tiles, const std::function<void(int)>& render_tile);

}  // namespace rtlab::detail
