#pragma once
/// \brief Simplex noise (Perlin 2001) in 2D and 3D: gradient noise summed over the corners of a simplex.
#include <array>
#include <cstdint>

namespace rtlab {

/// \brief Simplex noise: the skewed simplex lattice, a radial kernel (0.5 - r^2)^4 per corner, the same
/// gradient sets as PerlinNoise. The kernel radius r^2 = 0.5 (not the 0.6 often used in 3D) keeps every
/// corner's contribution zero before the point leaves that corner's simplices, so the noise has no
/// small jumps at simplex borders. Output scaled to about [-1, 1]; 0 at lattice points. Double input
/// for the same reason as PerlinNoise; non-finite input gives 0.
class SimplexNoise {
public:
    explicit SimplexNoise(std::uint64_t seed = 0);

    float eval(double x, double y) const;
    float eval(double x, double y, double z) const;

private:
    std::array<std::uint8_t, 512> m_perm{};
};

}  // namespace rtlab
