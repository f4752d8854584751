#pragma once
/// \brief Ken Perlin's improved gradient noise ("Improving Noise", SIGGRAPH 2002) in 2D and 3D.
#include <array>
#include <cstdint>

namespace rtlab {

/// \brief Improved Perlin noise: quintic fade 6t^5 - 15t^4 + 10t^3 (C2 across cells), the 12 cube-edge
/// gradients in 3D (8 directions in 2D), a 256-entry permutation shuffled from the seed.
///
/// Properties the tests hold it to: 0 at every integer lattice point; continuous value and gradient
/// across cell borders; |n| < 1; period 256 in every axis. Coordinates are doubles so that the lattice
/// cell and the fraction inside it stay exact far from the origin (a float at 1e5 keeps only 7 bits of
/// fraction, and scaling by an fBm frequency would lose those too). Non-finite input gives 0.
class PerlinNoise {
public:
    explicit PerlinNoise(std::uint64_t seed = 0);

    float eval(double x, double y) const;
    float eval(double x, double y, double z) const;

private:
    std::array<std::uint8_t, 512> m_perm{};  // the permutation twice, so perm[perm[i] + j] needs no wrap
};

}  // namespace rtlab
