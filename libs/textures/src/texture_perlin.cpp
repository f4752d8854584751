// Texture "perlin": Ken Perlin's improved noise (2002) and the patterns built from it.
//
// The value t in [0, 1] blends color1 (t = 0) into color2 (t = 1):
//   pattern "noise"       t = 0.5 + 0.5 n(p)
//   pattern "fbm"         t = 0.5 + 0.5 sum_k gain^k n(lacunarity^k p) / sum_k gain^k
//   pattern "turbulence"  t = sum_k gain^k |n(lacunarity^k p)| / sum_k gain^k
//   pattern "marble"      t = 0.5 + 0.5 sin(2 pi stripes p.x + distortion turbulence(p))
// where p = scale * uv (dimension 2) or scale * lookup.point (dimension 3, object space). A non-finite
// p gives t = 0. color1 and color2 are each a colour (one number or [r, g, b]) or a nested texture, which
// sees the unmodified lookup (rtlab/textures/texture_param.hpp).
//
// Parameters
//   dimension    2 (uv) or 3 (object-space point)         default 3
//   pattern      noise | fbm | turbulence | marble         default noise
//   scale        coordinate multiplier (feature size 1/scale), > 0   default 1
//   octaves      1 .. 24 (fbm, turbulence, marble)         default 6
//   lacunarity   frequency ratio between octaves, > 0      default 2
//   gain         amplitude ratio between octaves, > 0      default 0.5
//   stripes      marble stripes per unit of p.x, >= 0      default 1
//   distortion   marble turbulence strength                default 4
//   color1       colour or texture at t = 0                default 0
//   color2       colour or texture at t = 1                default 1
//   seed         permutation seed, 0 .. 2^31 - 1           default 0
#include <rtlab/textures/perlin_noise.hpp>

#include "noise_pattern.hpp"

namespace rtlab::detail {

void register_perlin(TextureRegistry& registry) {
    registry.add(
        "perlin",
        [](const Params& p) -> std::shared_ptr<Texture> {
            return std::make_shared<NoisePatternTexture<PerlinNoise>>(read_noise_settings(p));
        },
        noise_spec("improved Perlin noise (2002)"));
}

}  // namespace rtlab::detail
