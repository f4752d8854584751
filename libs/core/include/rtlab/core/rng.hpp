#pragma once
/// \brief Reproducible random numbers (PCG32), one independent stream per pixel.
#include <rtlab/core/math.hpp>

#include <pcg_random.hpp>

#include <cstdint>

namespace rtlab {

/// \brief A PCG32 generator. Streams derived from (seed, pixel) make a render independent of how
/// pixels are distributed over threads: the same seed gives the same image with any thread count.
class Rng {
public:
    explicit Rng(std::uint64_t seed = 0x853c49e6748fea9bULL, std::uint64_t stream = 0) : m_gen(seed, stream) {}

    /// The generator for pixel (x, y) of a render with the given seed.
    static Rng for_pixel(std::uint64_t seed, std::uint32_t x, std::uint32_t y) {
        return Rng(seed, (static_cast<std::uint64_t>(y) << 32) | x);
    }

    std::uint32_t next_u32() { return m_gen(); }
    /// Uniform in [0, bound) without modulo bias.
    std::uint32_t uniform_u32(std::uint32_t bound) { return m_gen(bound); }
    /// Uniform in [0, 1): 24 random mantissa bits, never exactly 1.
    float uniform() { return static_cast<float>(m_gen() >> 8) * 0x1p-24f; }
    Vec2 uniform2() {
        float a = uniform();
        return {a, uniform()};
    }
    void advance(std::uint64_t delta) { m_gen.advance(delta); }

private:
    pcg32 m_gen;
};

}  // namespace rtlab
