#pragma once
// The patterns "perlin" and "simplex" share: plain noise, fBm, turbulence and marble over a noise type,
// in 2D (uv) or 3D (object-space point), mapped to a blend of two colours.
#include <rtlab/textures/fractal_noise.hpp>

#include "texture_params.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace rtlab::detail {

enum class NoisePattern { noise, fbm, turbulence, marble };

struct NoiseSettings {
    int dimension = 3;
    NoisePattern pattern = NoisePattern::noise;
    double scale = 1.0;
    FractalParams fractal{};
    double stripes = 1.0;
    double distortion = 4.0;
    std::shared_ptr<const Texture> color1, color2;  ///< colours or nested textures
    std::uint64_t seed = 0;
};

/// Reads the parameters listed in noise_doc() and checks them.
NoiseSettings read_noise_settings(const Params& params);
/// The declaration of a noise texture's parameters (read_noise_settings) with `what` in its doc.
TypeSpec noise_spec(const std::string& what);

/// \brief A noise pattern: t in [0, 1] blends color1 (t = 0) to color2 (t = 1).
template <class Noise>
class NoisePatternTexture final : public Texture {
public:
    explicit NoisePatternTexture(const NoiseSettings& s)
        : m_s(s), m_noise(s.seed), m_constant1(s.color1->constant()), m_constant2(s.color2->constant()) {}

    /// The pattern value t in [0, 1] before colouring.
    float pattern(const TextureLookup& q) const {
        const double s = m_s.scale;
        // A non-finite point gives t = 0 (color1) for every pattern.
        const bool finite = m_s.dimension == 2 ? std::isfinite(q.uv.x) && std::isfinite(q.uv.y) : is_finite(q.point);
        if (!finite) return 0.0f;
        if (m_s.dimension == 2) return shade(q.uv.x * s, [&](auto&& f) { return f(q.uv.x * s, q.uv.y * s); });
        return shade(q.point.x * s, [&](auto&& f) { return f(q.point.x * s, q.point.y * s, q.point.z * s); });
    }

    RGB eval(const TextureLookup& q) const override {
        const RGB c1 = m_constant1 ? *m_constant1 : m_s.color1->eval(q);
        const RGB c2 = m_constant2 ? *m_constant2 : m_s.color2->eval(q);
        return lerp(c1, c2, pattern(q));
    }

private:
    // `at` calls its argument with the scaled coordinates (2 or 3 doubles).
    template <class At>
    float shade(double x, At&& at) const {
        const auto& fr = m_s.fractal;
        float t = 0.0f;
        switch (m_s.pattern) {
            case NoisePattern::noise:
                t = 0.5f + 0.5f * at([&](auto... c) { return m_noise.eval(c...); });
                break;
            case NoisePattern::fbm:
                t = 0.5f + 0.5f * at([&](auto... c) { return fbm(m_noise, c..., fr); });
                break;
            case NoisePattern::turbulence:
                t = at([&](auto... c) { return turbulence(m_noise, c..., fr); });
                break;
            case NoisePattern::marble: {
                const float turb = at([&](auto... c) { return turbulence(m_noise, c..., fr); });
                const double phase = 2.0 * std::numbers::pi * m_s.stripes * x + m_s.distortion * turb;
                t = static_cast<float>(0.5 + 0.5 * std::sin(phase));
                break;
            }
        }
        return std::isfinite(t) ? std::clamp(t, 0.0f, 1.0f) : 0.0f;
    }

    NoiseSettings m_s;
    Noise m_noise;
    const RGB* m_constant1;  // color1's value when it is a constant, read without a virtual call
    const RGB* m_constant2;
};

}  // namespace rtlab::detail
