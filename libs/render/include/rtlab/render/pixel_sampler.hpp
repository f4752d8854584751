#pragma once
/// \brief Where in a pixel the samples go: the anti-aliasing patterns.
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/core/sample_hash.hpp>

#include <cstdint>
#include <string_view>
#include <vector>

namespace rtlab {

/// none: the pixel centre once; grid: a regular sqrt(spp) x sqrt(spp) grid; random: uniform;
/// jittered: one uniform sample in each cell of the grid (stratified); adaptive: Whitted's corner
/// subdivision on a dyadic lattice (see AdaptiveSettings), which is no fixed pattern; sobol: Owen-scrambled Sobol
/// points (rtlab/core/low_discrepancy.hpp), progressive: spp samples exactly, any prefix well stratified, rendered
/// by render_progressive() (rtlab/render/progressive.hpp), whose integrators may draw their own dimensions from the
/// same sequence.
enum class PixelPattern { none, grid, random, jittered, adaptive, sobol };

/// "none", "grid", "random", "jittered", "adaptive" or "sobol"; throws rtlab::Error listing them otherwise.
PixelPattern parse_pixel_pattern(std::string_view name);
std::string_view pixel_pattern_name(PixelPattern pattern);

/// SampleKey dimensions the renderer uses for the camera (pixel jitter u, v; lens u, v). They sit far
/// above the small dimension numbers an integrator uses for its own samples of the same key.
inline constexpr std::uint32_t kPixelJitterDimension = 0x80000000u;
inline constexpr std::uint32_t kLensDimension = 0x80000002u;

/// Largest samples-per-pixel count the fixed patterns accept.
inline constexpr int kMaxSamplesPerPixel = 1 << 16;

/// How many samples a fixed pattern takes for spp: 1 for none, spp for random and sobol, and spp rounded up to the
/// next square for grid and jittered. Throws rtlab::Error for spp outside [1, kMaxSamplesPerPixel] or
/// the adaptive pattern.
int pattern_sample_count(PixelPattern pattern, int spp);

/// Offset in [0, 1)^2 of sample `index` (< pattern_sample_count) of the pixel whose key is `pixel`
/// (its x, y are the pixel's; the sample field is replaced by index). A pure function of its arguments.
Vec2 pattern_sample(PixelPattern pattern, int spp, int index, SampleKey pixel);

/// All offsets of a fixed pattern, in sample order.
std::vector<Vec2> pixel_samples(PixelPattern pattern, int spp, const SampleKey& pixel);

/// \brief Whitted's adaptive supersampling. Corners of a pixel are traced on the lattice of positions
/// (x + i / 2^max_depth, y + j / 2^max_depth); a square is split into four while any two of its four
/// corners have display_difference > threshold and it is larger than one lattice step, so a pixel
/// traces at most (2^max_depth + 1)^2 rays whatever the colours. The pixel is the mean of its four
/// quarters' values, a square's value being its corners' mean when it is not split.
struct AdaptiveSettings {
    int max_depth = 3;       ///< in [0, kMaxAdaptiveDepth]; 0 traces the four corners only
    float threshold = 0.3f;  ///< POV-Ray's default +A0.3
};
inline constexpr int kMaxAdaptiveDepth = 8;

/// POV-Ray's +AM2 colour distance: |r1 - r2| + |g1 - g2| + |b1 - b2| of the colours clamped to [0, 1]
/// per component (linear values, before tone mapping; POV-Ray 3.7 compares after applying its
/// Antialias_Gamma, default 2.5, so compare with +AG1). A NaN component differs by 1 from anything, NaN
/// included, so a NaN corner always splits its square (down to the depth cap). In [0, 3].
float display_difference(const RGB& a, const RGB& b);

}  // namespace rtlab
