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

TypeSpec noise_spec(const std::string& what) {
    TypeSpec s(what +
               " in 2D (uv) or 3D (object-space point); t in [0, 1] blends color1 to color2: noise and fbm "
               "give t = 0.5 + 0.5 n, turbulence t = sum |n|, marble t = 0.5 + 0.5 sin(2 pi stripes x + "
               "distortion turbulence)");
    s.add("dimension", ParamKind::integer, "2: by uv; 3: by the object-space point").defaults("3").range(2, 3);
    s.add("pattern", ParamKind::word, "what t is made of")
        .defaults("noise")
        .allow({"noise", "fbm", "turbulence", "marble"});
    s.add("scale", ParamKind::number, "coordinate multiplier (> 0)").defaults("1").at_least(0);
    s.add("octaves", ParamKind::integer, "noise layers of fbm, turbulence and marble").defaults("6").range(1, 24);
    s.add("lacunarity", ParamKind::number, "frequency factor from one octave to the next (> 0)")
        .defaults("2")
        .at_least(0);
    s.add("gain", ParamKind::number, "amplitude factor from one octave to the next (> 0)").defaults("0.5").at_least(0);
    s.add("stripes", ParamKind::number, "marble: stripes per unit x").defaults("1").at_least(0);
    s.add("distortion", ParamKind::number, "marble: how far turbulence bends the stripes").defaults("4");
    add_two_colours(s, "t = 0", "0", "t = 1", "1");
    s.add("seed", ParamKind::integer, "permutation seed").defaults("0").range(0, 2147483647);
    return s;
}

}  // namespace rtlab::detail
