// Improved Perlin noise, written from the published description (K. Perlin, "Improving Noise",
// SIGGRAPH 2002): hash the cell corners through a permutation, take the dot product of each corner's
// gradient with the offset to that corner, and blend with the quintic fade.
#include <rtlab/textures/perlin_noise.hpp>

#include "noise_lattice.hpp"

#include <cmath>

namespace rtlab {

namespace {
// Extremes of the unscaled noise, found by random search with hill climbing over 2 million points
// and two seeds: 1.000 in 2D (reached at cell centres with four diagonal gradients aligned) and about
// 1.02 in 3D. The 3D scale keeps |n| below 1 with margin.
constexpr float kScale2 = 1.0f;
constexpr float kScale3 = 0.95f;

}  // namespace

PerlinNoise::PerlinNoise(std::uint64_t seed) : m_perm(detail::make_permutation(seed)) {}

float PerlinNoise::eval(double x, double y) const {
    if (!std::isfinite(x) || !std::isfinite(y)) return 0.0f;
    const auto [xi, fx] = detail::split_lattice(x);
    const auto [yi, fy] = detail::split_lattice(y);
    const auto& p = m_perm;
    const int a = p[xi] + yi, b = p[xi + 1] + yi;
    const float u = detail::fade(fx), v = detail::fade(fy);
    const float n00 = detail::grad_dot2(p[a], fx, fy);
    const float n10 = detail::grad_dot2(p[b], fx - 1.0f, fy);
    const float n01 = detail::grad_dot2(p[a + 1], fx, fy - 1.0f);
    const float n11 = detail::grad_dot2(p[b + 1], fx - 1.0f, fy - 1.0f);
    return kScale2 * detail::lerp(detail::lerp(n00, n10, u), detail::lerp(n01, n11, u), v);
}

float PerlinNoise::eval(double x, double y, double z) const {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return 0.0f;
    const auto [xi, fx] = detail::split_lattice(x);
    const auto [yi, fy] = detail::split_lattice(y);
    const auto [zi, fz] = detail::split_lattice(z);
    const auto& p = m_perm;
    const int a = p[xi] + yi, aa = p[a] + zi, ab = p[a + 1] + zi;
    const int b = p[xi + 1] + yi, ba = p[b] + zi, bb = p[b + 1] + zi;
    const float u = detail::fade(fx), v = detail::fade(fy), w = detail::fade(fz);
    const float gx = fx - 1.0f, gy = fy - 1.0f, gz = fz - 1.0f;
    using detail::lerp;
    const float z0 = lerp(lerp(detail::grad_dot3(p[aa], fx, fy, fz), detail::grad_dot3(p[ba], gx, fy, fz), u),
                          lerp(detail::grad_dot3(p[ab], fx, gy, fz), detail::grad_dot3(p[bb], gx, gy, fz), u), v);
    const float z1 =
        lerp(lerp(detail::grad_dot3(p[aa + 1], fx, fy, gz), detail::grad_dot3(p[ba + 1], gx, fy, gz), u),
             lerp(detail::grad_dot3(p[ab + 1], fx, gy, gz), detail::grad_dot3(p[bb + 1], gx, gy, gz), u), v);
    return kScale3 * lerp(z0, z1, w);
}

}  // namespace rtlab
