// Plugin module "wood": a procedural (solid) wood texture, registered as texture "wood".
//
// A log whose trunk runs along an axis through the origin of object space: the growth rings are
// cylinders around that axis, spaced 1 / rings apart, each light (early wood) turning to dark (late wood)
// towards its outer edge. Perlin noise shifts the rings by up to `turbulence` ring widths, so they wobble
// as real ones do. A solid texture: it reads TextureLookup::point, so cuts through an object show the
// rings across the cut and the grain along it.
//
// Parameters
//   light        early-wood colour                                   default (0.78, 0.56, 0.33)
//   dark         late-wood colour                                    default (0.42, 0.24, 0.11)
//   rings        rings per unit distance from the axis, > 0          default 6
//   turbulence   noise displacement of the rings, in ring widths     default 0.3 (0: perfect circles)
//   noise_scale  frequency of that noise, per unit, > 0              default 1.5
//   axis         trunk direction: "x", "y" or "z"                    default "y"
//   seed         noise seed (integer >= 0)                           default 0
#include <rtlab/core/param_checks.hpp>
#include <rtlab/scene/plugin_abi.hpp>
#include <rtlab/textures/perlin_noise.hpp>

#include <algorithm>
#include <cmath>

namespace {

using namespace rtlab;

class WoodTexture final : public Texture {
public:
    WoodTexture(RGB light, RGB dark, float rings, float turbulence, float noise_scale, int axis, int seed)
        : m_light(light),
          m_dark(dark),
          m_rings(rings),
          m_turbulence(turbulence),
          m_noise_scale(noise_scale),
          m_axis(axis),
          m_noise(static_cast<std::uint64_t>(seed)) {}

    RGB eval(const TextureLookup& q) const override {
        const Vec3 p = q.point;
        // The two coordinates across the trunk.
        const float a = m_axis == 0 ? p.y : p.x, b = m_axis == 2 ? p.y : p.z;
        const double r = std::sqrt(static_cast<double>(a) * a + static_cast<double>(b) * b);
        double phase = r * m_rings;
        if (m_turbulence > 0.0f)
            phase += m_turbulence * m_noise.eval(p.x * m_noise_scale, p.y * m_noise_scale, p.z * m_noise_scale);
        const double t = phase - std::floor(phase);  // position inside the ring: 0 inner edge, 1 outer
        const float late = static_cast<float>(smoothstep(0.55, 0.95, t));
        return m_light * (1.0f - late) + m_dark * late;
    }

private:
    static double smoothstep(double lo, double hi, double x) {
        const double s = std::clamp((x - lo) / (hi - lo), 0.0, 1.0);
        return s * s * (3.0 - 2.0 * s);
    }

    RGB m_light, m_dark;
    float m_rings, m_turbulence, m_noise_scale;
    int m_axis;
    PerlinNoise m_noise;
};

std::shared_ptr<Texture> make_wood(const Params& p) {
    const RGB light = finite_rgb(p, "light", RGB(0.78f, 0.56f, 0.33f));
    const RGB dark = finite_rgb(p, "dark", RGB(0.42f, 0.24f, 0.11f));
    const float rings = positive_float(p, "rings", 6.0f);
    const float turbulence = positive_float(p, "turbulence", 0.3f, true);
    const float noise_scale = positive_float(p, "noise_scale", 1.5f);
    const std::string axis = one_of(p, "axis", "y", {"x", "y", "z"});
    const int seed = bounded_int(p, "seed", 0, 0, 1 << 30);
    return std::make_shared<WoodTexture>(light, dark, rings, turbulence, noise_scale, axis[0] - 'x', seed);
}

TypeSpec wood_spec() {
    TypeSpec s("solid wood: growth rings around an axis through the object's origin");
    s.add("light", ParamKind::colour, "the early wood between rings").defaults("[0.78, 0.56, 0.33]");
    s.add("dark", ParamKind::colour, "the rings").defaults("[0.42, 0.24, 0.11]");
    s.add("rings", ParamKind::number, "rings per unit (> 0)").defaults("6").at_least(0);
    s.add("turbulence", ParamKind::number, "noise in the ring widths").defaults("0.3").at_least(0);
    s.add("noise_scale", ParamKind::number, "frequency of that noise (> 0)").defaults("1.5").at_least(0);
    s.add("axis", ParamKind::word, "the trunk's axis").defaults("y").allow({"x", "y", "z"});
    s.add("seed", ParamKind::integer, "which noise").defaults("0").range(0, 1 << 30);
    return s;
}

void register_types(rtlab::PluginRegistries& r) { r.textures.add("wood", make_wood, wood_spec()); }

}  // namespace

RTLAB_DEFINE_PLUGIN("wood: a procedural wood texture", register_types)
