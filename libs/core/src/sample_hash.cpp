#include <rtlab/core/sample_hash.hpp>

namespace rtlab {

namespace {
// The splitmix64 finaliser (Steele, Lea and Flood 2014): a bijection on 64 bits whose every output
// bit depends on every input bit, so chaining it over the fields decorrelates neighbouring keys.
std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}
}  // namespace

std::uint64_t sample_hash(const SampleKey& key, std::uint32_t dimension) {
    std::uint64_t h = mix(key.seed);
    h = mix(h ^ ((static_cast<std::uint64_t>(key.y) << 32) | key.x));
    h = mix(h ^ ((static_cast<std::uint64_t>(key.bounce) << 32) | key.sample));
    return mix(h ^ dimension);
}

}  // namespace rtlab
