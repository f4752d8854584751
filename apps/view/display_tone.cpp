#include "display_tone.hpp"

#include <algorithm>
#include <cmath>

namespace rtlab::view {

const std::vector<std::string>& tone_choice_names() {
    static const std::vector<std::string> names{"none", "reinhard", "ward", "aces"};
    return names;
}

bool parse_tone_choice(const std::string& name, ToneChoice& out) {
    const auto& names = tone_choice_names();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) return false;
    out = static_cast<ToneChoice>(it - names.begin());
    return true;
}

ToneParams tone_params(ToneChoice op, float stops, const std::vector<float>& rgb,
                       const std::vector<std::uint8_t>& rendered) {
    ToneParams p;
    p.op = op;
    const double exposure = std::exp2(static_cast<double>(stops));
    if (op == ToneChoice::none || op == ToneChoice::aces) {
        p.scale = static_cast<float>(exposure);
        return p;
    }
    // The statistics of rtlab::measure_luminance (delta 1e-4, negative components as 0, non-finite pixels left
    // out), over the exposed pixels that hold samples.
    constexpr double kDelta = 1e-4;
    double log_sum = 0.0, max_luminance = 0.0;
    std::size_t valid = 0;
    const std::size_t pixels = rgb.size() / 3;
    for (std::size_t i = 0; i < pixels; ++i) {
        if (!rendered.empty() && !rendered[i]) continue;
        RGB c(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
        if (!c.is_finite()) continue;
        c = RGB(std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f)) * static_cast<float>(exposure);
        const double l = c.luminance();
        log_sum += std::log(kDelta + l);
        max_luminance = std::max(max_luminance, l);
        ++valid;
    }
    const double log_average = valid > 0 ? std::exp(log_sum / static_cast<double>(valid)) : kDelta;
    if (op == ToneChoice::reinhard) {
        const double scale = 0.18 / log_average;
        const double white = scale * max_luminance;
        p.scale = static_cast<float>(scale * exposure);
        p.inv_white2 = (white > 0.0 && std::isfinite(white)) ? static_cast<float>(1.0 / (white * white)) : 0.0f;
    } else {
        constexpr double kLdMax = 100.0;
        const double m =
            std::pow((1.219 + std::pow(kLdMax / 2.0, 0.4)) / (1.219 + std::pow(log_average, 0.4)), 2.5) / kLdMax;
        p.scale = static_cast<float>(m * exposure);
    }
    return p;
}

namespace {
float aces_fit(float x) { return x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f); }
float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }  // NaN -> 0
}  // namespace

RGB tone_map(const ToneParams& p, const RGB& linear) {
    RGB out;
    switch (p.op) {
        case ToneChoice::none:
        case ToneChoice::ward:
            out = linear * p.scale;
            break;
        case ToneChoice::aces: {
            const RGB x = linear * p.scale;
            out = RGB(aces_fit(std::min(x.r, 1e18f)), aces_fit(std::min(x.g, 1e18f)), aces_fit(std::min(x.b, 1e18f)));
            break;
        }
        case ToneChoice::reinhard: {
            const float lw = linear.luminance();
            if (!(lw > 0.0f)) return RGB{};
            const float l = p.scale * lw;
            const float ld = l * (1.0f + l * p.inv_white2) / (1.0f + l);
            out = linear * (ld / lw);
            break;
        }
    }
    return RGB(clamp01(out.r), clamp01(out.g), clamp01(out.b));
}

}  // namespace rtlab::view
