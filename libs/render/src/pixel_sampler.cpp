#include <rtlab/core/error.hpp>
#include <rtlab/render/pixel_sampler.hpp>

#include <cmath>
#include <string>

namespace rtlab {

PixelPattern parse_pixel_pattern(std::string_view name) {
    if (name == "none") return PixelPattern::none;
    if (name == "grid") return PixelPattern::grid;
    if (name == "random") return PixelPattern::random;
    if (name == "jittered") return PixelPattern::jittered;
    throw Error("unknown anti-aliasing pattern '" + std::string(name) + "'; known: none, grid, random, jittered");
}

std::vector<Vec2> pixel_samples(PixelPattern pattern, int spp, Rng& rng) {
    if (spp < 1) throw Error("samples per pixel must be at least 1, got " + std::to_string(spp));
    std::vector<Vec2> out;
    if (pattern == PixelPattern::none) return {Vec2(0.5f)};
    if (pattern == PixelPattern::random) {
        out.reserve(static_cast<std::size_t>(spp));
        for (int i = 0; i < spp; ++i) out.push_back(rng.uniform2());
        return out;
    }
    const int n = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(spp))));
    const float cell = 1.0f / static_cast<float>(n);
    out.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const Vec2 offset = pattern == PixelPattern::grid ? Vec2(0.5f) : rng.uniform2();
            // min() keeps a jitter of 1 - 2^-24 from rounding up onto the next cell's border.
            out.emplace_back(std::min((static_cast<float>(i) + offset.x) * cell, 0x1.fffffep-1f),
                             std::min((static_cast<float>(j) + offset.y) * cell, 0x1.fffffep-1f));
        }
    }
    return out;
}

}  // namespace rtlab
