#include <rtlab/core/error.hpp>
#include <rtlab/core/sample_stream.hpp>
#include <rtlab/render/pixel_sampler.hpp>

#include <cmath>
#include <string>

namespace rtlab {

PixelPattern parse_pixel_pattern(std::string_view name) {
    if (name == "none") return PixelPattern::none;
    if (name == "grid") return PixelPattern::grid;
    if (name == "random") return PixelPattern::random;
    if (name == "jittered") return PixelPattern::jittered;
    if (name == "adaptive") return PixelPattern::adaptive;
    if (name == "sobol") return PixelPattern::sobol;
    throw Error("unknown anti-aliasing pattern '" + std::string(name) +
                "'; known: none, grid, random, jittered, adaptive, sobol");
}

std::string_view pixel_pattern_name(PixelPattern pattern) {
    switch (pattern) {
        case PixelPattern::none:
            return "none";
        case PixelPattern::grid:
            return "grid";
        case PixelPattern::random:
            return "random";
        case PixelPattern::jittered:
            return "jittered";
        case PixelPattern::adaptive:
            return "adaptive";
        case PixelPattern::sobol:
            return "sobol";
    }
    return "?";
}

namespace {
int grid_side(int spp) {
    int n = static_cast<int>(std::sqrt(static_cast<double>(spp)));
    while (n * n < spp) ++n;
    return n;
}
}  // namespace

int pattern_sample_count(PixelPattern pattern, int spp) {
    if (spp < 1 || spp > kMaxSamplesPerPixel)
        throw Error("samples per pixel must lie in [1, " + std::to_string(kMaxSamplesPerPixel) + "], got " +
                    std::to_string(spp));
    switch (pattern) {
        case PixelPattern::none:
            return 1;
        case PixelPattern::random:
        case PixelPattern::sobol:
            return spp;
        case PixelPattern::grid:
        case PixelPattern::jittered: {
            const int n = grid_side(spp);
            return n * n;
        }
        case PixelPattern::adaptive:
            break;
    }
    throw Error("the adaptive pattern has no fixed sample positions");
}

Vec2 pattern_sample(PixelPattern pattern, int spp, int index, SampleKey pixel) {
    pixel.sample = static_cast<std::uint32_t>(index);
    switch (pattern) {
        case PixelPattern::none:
            return Vec2(0.5f);
        case PixelPattern::random:
            return sample_uniform2(pixel, kPixelJitterDimension);
        case PixelPattern::sobol:
            return SampleStream(SampleSequence::sobol, pixel).get2d(kPixelPair);
        case PixelPattern::grid:
        case PixelPattern::jittered: {
            const int n = grid_side(spp);
            const Vec2 offset =
                pattern == PixelPattern::grid ? Vec2(0.5f) : sample_uniform2(pixel, kPixelJitterDimension);
            const float cell = 1.0f / static_cast<float>(n);
            // min() keeps a jitter of 1 - 2^-24 from rounding up onto the next cell's border.
            return {std::min((static_cast<float>(index % n) + offset.x) * cell, 0x1.fffffep-1f),
                    std::min((static_cast<float>(index / n) + offset.y) * cell, 0x1.fffffep-1f)};
        }
        case PixelPattern::adaptive:
            break;
    }
    throw Error("the adaptive pattern has no fixed sample positions");
}

std::vector<Vec2> pixel_samples(PixelPattern pattern, int spp, const SampleKey& pixel) {
    const int n = pattern_sample_count(pattern, spp);
    std::vector<Vec2> out;
    out.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) out.push_back(pattern_sample(pattern, spp, i, pixel));
    return out;
}

namespace {
float clamped_difference(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return 1.0f;
    return std::abs(std::clamp(a, 0.0f, 1.0f) - std::clamp(b, 0.0f, 1.0f));
}
}  // namespace

float display_difference(const RGB& a, const RGB& b) {
    return clamped_difference(a.r, b.r) + clamped_difference(a.g, b.g) + clamped_difference(a.b, b.b);
}

}  // namespace rtlab
