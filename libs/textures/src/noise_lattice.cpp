#include "noise_lattice.hpp"

namespace rtlab::detail {

namespace {
// SplitMix64 (Steele, Lea and Flood 2014): a tiny generator whose only job is a fixed shuffle per seed.
std::uint64_t splitmix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}
}  // namespace

std::array<std::uint8_t, 512> make_permutation(std::uint64_t seed) {
    std::array<std::uint8_t, 256> p{};
    for (int i = 0; i < 256; ++i) p[i] = static_cast<std::uint8_t>(i);
    std::uint64_t state = seed;
    for (int i = 255; i > 0; --i) {
        // Modulo bias is irrelevant for a shuffle that only has to look random.
        const auto j = static_cast<int>(splitmix64(state) % static_cast<std::uint64_t>(i + 1));
        std::swap(p[i], p[j]);
    }
    std::array<std::uint8_t, 512> out{};
    for (int i = 0; i < 512; ++i) out[i] = p[i & 255];
    return out;
}

}  // namespace rtlab::detail
