// Simplex noise, written from Perlin's description (SIGGRAPH 2001 course notes "Noise hardware") and
// S. Gustavson's explanation "Simplex noise demystified" (2005): skew space so the simplex lattice
// becomes the integer lattice, find the simplex by ranking the offsets, and sum one radially attenuated
// gradient ramp per corner.
#include <rtlab/textures/simplex_noise.hpp>

#include "noise_lattice.hpp"

#include <cmath>

namespace rtlab {

namespace {
const double kF2 = 0.5 * (std::sqrt(3.0) - 1.0);
const double kG2 = (3.0 - std::sqrt(3.0)) / 6.0;
constexpr double kF3 = 1.0 / 3.0;
constexpr double kG3 = 1.0 / 6.0;

// The unscaled extremes, found by random search with hill climbing, are 0.01426 (2D) and 0.01301 (3D);
// these scales bring them to about 0.97 and 0.98.
constexpr float kScale2 = 68.0f;
constexpr float kScale3 = 75.0f;

// (0.5 - r^2)^4 g.d, zero outside r^2 = 0.5.
float corner2(int hash, float x, float y) {
    const float t = 0.5f - x * x - y * y;
    if (t <= 0.0f) return 0.0f;
    const float t2 = t * t;
    return t2 * t2 * detail::grad_dot2(hash, x, y);
}

float corner3(int hash, float x, float y, float z) {
    const float t = 0.5f - x * x - y * y - z * z;
    if (t <= 0.0f) return 0.0f;
    const float t2 = t * t;
    return t2 * t2 * detail::grad_dot3(hash, x, y, z);
}
}  // namespace

SimplexNoise::SimplexNoise(std::uint64_t seed) : m_perm(detail::make_permutation(seed)) {}

float SimplexNoise::eval(double x, double y) const {
    if (!std::isfinite(x) || !std::isfinite(y)) return 0.0f;
    const double s = (x + y) * kF2;
    const double fi = detail::fast_floor(x + s), fj = detail::fast_floor(y + s);
    const double t = (fi + fj) * kG2;
    // Offsets from the cell origin, unskewed; in double so they stay exact far from the origin.
    const auto x0 = static_cast<float>((x - fi) + t), y0 = static_cast<float>((y - fj) + t);
    const int i1 = x0 > y0 ? 1 : 0, j1 = 1 - i1;
    const auto g2 = static_cast<float>(kG2);
    const float x1 = x0 - static_cast<float>(i1) + g2, y1 = y0 - static_cast<float>(j1) + g2;
    const float x2 = x0 - 1.0f + 2.0f * g2, y2 = y0 - 1.0f + 2.0f * g2;
    const int ii = detail::cell_mod_256(fi), jj = detail::cell_mod_256(fj);
    const auto& p = m_perm;
    const float n = corner2(p[ii + p[jj]], x0, y0) + corner2(p[ii + i1 + p[jj + j1]], x1, y1) +
                    corner2(p[ii + 1 + p[jj + 1]], x2, y2);
    return kScale2 * n;
}

float SimplexNoise::eval(double x, double y, double z) const {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return 0.0f;
    const double s = (x + y + z) * kF3;
    const double fi = detail::fast_floor(x + s), fj = detail::fast_floor(y + s), fk = detail::fast_floor(z + s);
    const double t = (fi + fj + fk) * kG3;
    const auto x0 = static_cast<float>((x - fi) + t), y0 = static_cast<float>((y - fj) + t),
               z0 = static_cast<float>((z - fk) + t);
    // The simplex is picked by the order of the offsets: walk from (0,0,0) to (1,1,1) along the axes
    // in decreasing order of offset.
    int i1, j1, k1, i2, j2, k2;
    if (x0 >= y0) {
        if (y0 >= z0) {
            i1 = 1;
            j1 = 0;
            k1 = 0;
            i2 = 1;
            j2 = 1;
            k2 = 0;
        } else if (x0 >= z0) {
            i1 = 1;
            j1 = 0;
            k1 = 0;
            i2 = 1;
            j2 = 0;
            k2 = 1;
        } else {
            i1 = 0;
            j1 = 0;
            k1 = 1;
            i2 = 1;
            j2 = 0;
            k2 = 1;
        }
    } else {
        if (y0 < z0) {
            i1 = 0;
            j1 = 0;
            k1 = 1;
            i2 = 0;
            j2 = 1;
            k2 = 1;
        } else if (x0 < z0) {
            i1 = 0;
            j1 = 1;
            k1 = 0;
            i2 = 0;
            j2 = 1;
            k2 = 1;
        } else {
            i1 = 0;
            j1 = 1;
            k1 = 0;
            i2 = 1;
            j2 = 1;
            k2 = 0;
        }
    }
    const auto g3 = static_cast<float>(kG3);
    auto f = [](int v) { return static_cast<float>(v); };
    const float x1 = x0 - f(i1) + g3, y1 = y0 - f(j1) + g3, z1 = z0 - f(k1) + g3;
    const float x2 = x0 - f(i2) + 2.0f * g3, y2 = y0 - f(j2) + 2.0f * g3, z2 = z0 - f(k2) + 2.0f * g3;
    const float x3 = x0 - 1.0f + 3.0f * g3, y3 = y0 - 1.0f + 3.0f * g3, z3 = z0 - 1.0f + 3.0f * g3;
    const int ii = detail::cell_mod_256(fi), jj = detail::cell_mod_256(fj), kk = detail::cell_mod_256(fk);
    const auto& p = m_perm;
    const float n = corner3(p[ii + p[jj + p[kk]]], x0, y0, z0) +
                    corner3(p[ii + i1 + p[jj + j1 + p[kk + k1]]], x1, y1, z1) +
                    corner3(p[ii + i2 + p[jj + j2 + p[kk + k2]]], x2, y2, z2) +
                    corner3(p[ii + 1 + p[jj + 1 + p[kk + 1]]], x3, y3, z3);
    return kScale3 * n;
}

}  // namespace rtlab
