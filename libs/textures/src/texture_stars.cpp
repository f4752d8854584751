// Texture "stars": a random star field by direction, for an environment. The sphere of directions is cut
// into the texel grid of a cube map `resolution` texels across a face; a cell is a star with probability
// `density`, of a random brightness and a slightly random blue. It is a step function of the direction
// (one value per cell), so a cube map baked from it at the same resolution holds it exactly: bake it
// (cubemap "bake") to filter it by levels. It stands in for a star-field photograph that is not at hand.
//
// Parameters
//   resolution  cells across a cube face, 1..8192       default 512
//   density     chance of a star per cell, [0, 1]       default 0.0025
//   seed        integer >= 0                            default 7
#include <rtlab/core/cube_face.hpp>
#include <rtlab/core/sample_hash.hpp>

#include "texture_params.hpp"

#include <algorithm>
#include <cstdint>

namespace rtlab {

namespace {

class StarsTexture final : public Texture {
public:
    StarsTexture(int resolution, float density, std::uint64_t seed)
        : m_resolution(resolution), m_density(density), m_seed(seed) {}

    RGB eval(const TextureLookup& q) const override {
        if (!is_finite(q.direction) || q.direction == Vec3(0.0f)) return {};
        const CubeFaceCoord c = cube_face_coord(q.direction);
        const float n = static_cast<float>(m_resolution);
        const auto cell = [&](float s) {
            return static_cast<std::uint32_t>(std::clamp(static_cast<int>(s * n), 0, m_resolution - 1));
        };
        const SampleKey key{m_seed, cell(c.s), cell(c.t), static_cast<std::uint32_t>(c.face), 0};
        if (!(sample_uniform(key, 0) < m_density)) return {};
        // Mostly faint stars, a few bright ones (the square of a uniform number leans towards 0).
        const float b = 0.3f + 2.0f * sample_uniform(key, 1) * sample_uniform(key, 1);
        return {b, b, b * (0.85f + 0.3f * sample_uniform(key, 2))};
    }

private:
    int m_resolution;
    float m_density;
    std::uint64_t m_seed;
};

}  // namespace

namespace detail {

namespace {
TypeSpec stars_spec() {
    TypeSpec s(
        "random star field by lookup.direction, one value per cell of a cube-face grid; bake it into a "
        "cubemap (\"bake\") to filter it");
    s.add("resolution", ParamKind::integer, "cells across a cube face").defaults("512").range(1, 8192);
    s.add("density", ParamKind::number, "chance of a star per cell").defaults("0.0025").range(0, 1);
    s.add("seed", ParamKind::integer, "which random field").defaults("7").range(0, 1 << 30);
    return s;
}
}  // namespace

void register_stars(TextureRegistry& registry) {
    registry.add(
        "stars",
        [](const Params& p) -> std::shared_ptr<Texture> {
            return std::make_shared<StarsTexture>(bounded_int(p, "resolution", 512, 1, 8192),
                                                  float_in_range(p, "density", 0.0025f, 0.0f, 1.0f),
                                                  static_cast<std::uint64_t>(bounded_int(p, "seed", 7, 0, 1 << 30)));
        },
        stars_spec());
}

}  // namespace detail
}  // namespace rtlab
