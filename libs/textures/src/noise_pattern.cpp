#include "noise_pattern.hpp"

namespace rtlab::detail {

NoiseSettings read_noise_settings(const Params& p) {
    NoiseSettings s;
    s.dimension = bounded_int(p, "dimension", 3, 2, 3);
    const std::string pattern = one_of(p, "pattern", "noise", {"noise", "fbm", "turbulence", "marble"});
    s.pattern = pattern == "noise"        ? NoisePattern::noise
                : pattern == "fbm"        ? NoisePattern::fbm
                : pattern == "turbulence" ? NoisePattern::turbulence
                                          : NoisePattern::marble;
    s.scale = positive_float(p, "scale", 1.0f);
    s.fractal.octaves = bounded_int(p, "octaves", 6, 1, 24);
    s.fractal.lacunarity = positive_float(p, "lacunarity", 2.0f);
    s.fractal.gain = positive_float(p, "gain", 0.5f);
    s.stripes = positive_float(p, "stripes", 1.0f, true);
    s.distortion = p.get_float("distortion", 4.0f);
    if (!std::isfinite(s.distortion)) fail_param(p, "distortion", "must be finite");
    s.color1 = texture_param(p, "color1", 0.0f);
    s.color2 = texture_param(p, "color2", 1.0f);
    s.seed = static_cast<std::uint64_t>(bounded_int(p, "seed", 0, 0, 2147483647));
    return s;
}

std::string noise_doc(const std::string& what) {
    return what +
           " in 2D (uv) or 3D (object-space point); t in [0, 1] blends color1 to color2. "
           "dimension: 2 or 3 (default 3); pattern: noise | fbm | turbulence | marble (default noise), "
           "noise and fbm give t = 0.5 + 0.5 n, turbulence t = sum |n|, marble t = 0.5 + 0.5 sin(2 pi stripes x + "
           "distortion turbulence); scale: coordinate multiplier (default 1); octaves 1..24 (default 6); "
           "lacunarity (default 2); gain (default 0.5); stripes >= 0 (default 1); distortion (default 4); "
           "color1: a colour or a texture (default 0); color2: a colour or a texture (default 1); seed: permutation "
           "seed 0..2^31-1 (default 0)";
}

}  // namespace rtlab::detail
