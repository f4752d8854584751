#pragma once
// Shared by the Perlin and simplex noise: the permutation table and the split of a coordinate into a
// lattice cell (mod 256) and an exact fraction.
#include <array>
#include <cmath>
#include <cstdint>

namespace rtlab::detail {

/// A lattice coordinate: the cell index reduced mod 256 and the offset inside the cell, in [0, 1].
struct LatticeSplit {
    int cell;
    float frac;
};

/// A lattice index reduced mod 256, from an integral double of any size (never converting an
/// out-of-range double to an integer, which would be undefined).
inline int cell_mod_256(double integral) {
    // The common case in integers (two's complement & 255 is the mod for negatives too); fmod, exact
    // but slow, only where a conversion to int64 could overflow.
    if (std::abs(integral) < 0x1p62) return static_cast<int>(static_cast<std::int64_t>(integral) & 255);
    double m = std::fmod(integral, 256.0);
    if (m < 0.0) m += 256.0;
    return static_cast<int>(m) & 255;
}

/// floor(x) without a libm call (the x86-64 baseline has no rounding instruction); |x| >= 2^62 is
/// already integral in double, so it is returned as it is. x must not be NaN.
inline double fast_floor(double x) {
    if (!(std::abs(x) < 0x1p62)) return x;
    const double t = static_cast<double>(static_cast<std::int64_t>(x));  // truncates toward zero, exact
    return t > x ? t - 1.0 : t;
}

/// x - floor(x) is exact in double, so the fraction is as accurate as the input however far out it is.
inline LatticeSplit split_lattice(double x) {
    const double fl = fast_floor(x);
    return {cell_mod_256(fl), static_cast<float>(x - fl)};
}

/// A permutation of 0..255 shuffled by seed (Fisher-Yates over a SplitMix64 stream), stored twice.
std::array<std::uint8_t, 512> make_permutation(std::uint64_t seed);

/// The quintic fade of improved noise: C2 at 0 and 1 (first and second derivatives vanish there).
inline float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

inline float lerp(float a, float b, float t) { return a + t * (b - a); }

// The 12 directions to the edge midpoints of a cube, padded to 16 with four of them repeated (the
// paper's choice: a mask of 4 hash bits instead of a modulo by 12).
constexpr signed char kGrad3[16][3] = {{1, 1, 0},  {-1, 1, 0},  {1, -1, 0}, {-1, -1, 0}, {1, 0, 1},  {-1, 0, 1},
                                       {1, 0, -1}, {-1, 0, -1}, {0, 1, 1},  {0, -1, 1},  {0, 1, -1}, {0, -1, -1},
                                       {1, 1, 0},  {-1, 1, 0},  {0, -1, 1}, {0, -1, -1}};
// Eight directions in 2D: the axes and the diagonals.
constexpr signed char kGrad2[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};

inline float grad_dot3(int hash, float x, float y, float z) {
    const signed char* g = kGrad3[hash & 15];
    return static_cast<float>(g[0]) * x + static_cast<float>(g[1]) * y + static_cast<float>(g[2]) * z;
}

inline float grad_dot2(int hash, float x, float y) {
    const signed char* g = kGrad2[hash & 7];
    return static_cast<float>(g[0]) * x + static_cast<float>(g[1]) * y;
}
}  // namespace rtlab::detail
