#pragma once
/// \brief Where in a pixel the samples go: the anti-aliasing patterns.
#include <rtlab/core/math.hpp>
#include <rtlab/core/rng.hpp>

#include <string_view>
#include <vector>

namespace rtlab {

/// none: the pixel centre once; grid: a regular sqrt(spp) x sqrt(spp) grid; random: uniform;
/// jittered: one uniform sample in each cell of the grid (stratified). Adaptive sampling builds on these.
enum class PixelPattern { none, grid, random, jittered };

/// "none", "grid", "random" or "jittered"; throws rtlab::Error listing them otherwise.
PixelPattern parse_pixel_pattern(std::string_view name);

/// Sample offsets in [0, 1)^2 within a pixel. grid and jittered round spp up to the next square.
std::vector<Vec2> pixel_samples(PixelPattern pattern, int spp, Rng& rng);

}  // namespace rtlab
