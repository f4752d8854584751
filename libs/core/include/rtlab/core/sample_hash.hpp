#pragma once
/// \brief Random numbers as pure functions of where they are used, so an image cannot depend on the
/// thread count, on tile order, or on which pixel computed a corner shared with its neighbour.
#include <rtlab/core/math.hpp>

#include <cstdint>

namespace rtlab {

/// \brief Where a random number is used: the render's seed, the sample's position on the global
/// sub-pixel lattice (pixel coordinate times the lattice resolution plus the sub-position, so corners
/// shared by neighbouring pixels have one key), the sample index within that position, and the bounce.
struct SampleKey {
    std::uint64_t seed = 0;
    std::uint32_t x = 0, y = 0;
    std::uint32_t sample = 0;
    std::uint32_t bounce = 0;
};

/// A well-mixed 64-bit hash of the key and a dimension (which number of the sample this is: lens u,
/// lens v, light sample u, ...). Any change of a field or the dimension gives an unrelated value.
std::uint64_t sample_hash(const SampleKey& key, std::uint32_t dimension);

/// Uniform in [0, 1) from sample_hash: 24 random mantissa bits, never exactly 1.
inline float sample_uniform(const SampleKey& key, std::uint32_t dimension) {
    return static_cast<float>(sample_hash(key, dimension) >> 40) * 0x1p-24f;
}

/// Two uniforms from dimensions `dimension` and `dimension + 1`.
inline Vec2 sample_uniform2(const SampleKey& key, std::uint32_t dimension) {
    return {sample_uniform(key, dimension), sample_uniform(key, dimension + 1)};
}

}  // namespace rtlab
