// reinhard: the photographic operator of Reinhard, Stark, Shirley and Ferwerda 2002, global version.
//   L = key / L_avg * L_w,  L_d = L (1 + L / L_white^2) / (1 + L),  display RGB = RGB * L_d / L_w
// L_avg is the log-average luminance (delta 1e-4). Parameters: key (default 0.18); white, the smallest
// scaled luminance mapped to pure white (default: the image's largest scaled luminance; 0 = infinite,
// the simple form L / (1 + L)).
#include <rtlab/core/error.hpp>

#include "global_operator.hpp"

#include <fmt/core.h>
#include <cmath>
#include <limits>
#include <optional>

namespace rtlab::tonemap {

class ReinhardOperator final : public ToneOperator {
public:
    ReinhardOperator(double key, std::optional<double> white) : m_key(key), m_white(white) {
        if (!(key > 0.0 && std::isfinite(key))) throw Error("tone operator 'reinhard': key must be positive");
        if (white && !(*white >= 0.0)) throw Error("tone operator 'reinhard': white must be >= 0 (0 for infinite)");
    }
    Image apply(const Image& hdr, ToneReport* report) const override {
        const LuminanceStats s = measure_luminance(hdr);
        const double scale = m_key / s.log_average;
        const double white = m_white ? *m_white : scale * s.max_luminance;
        const double inv_white2 = (white > 0.0 && std::isfinite(white)) ? 1.0 / (white * white) : 0.0;
        // The parameter was read as a float: printed as one ("0.18", not "0.18000000715255737").
        fill_report(report, s, scale,
                    fmt::format("reinhard: key {}, L_avg {:.6g}, white {}", static_cast<float>(m_key), s.log_average,
                                inv_white2 > 0.0 ? fmt::format("{:.6g}", white) : std::string("infinite")));
        return map_pixels(hdr, [scale, inv_white2](const RGB& c) {
            const double lw = c.luminance();
            if (!(lw > 0.0)) return RGB{};
            const double l = scale * lw;
            const double ld = l * (1.0 + l * inv_white2) / (1.0 + l);
            return c * static_cast<float>(ld / lw);
        });
    }

private:
    double m_key;
    std::optional<double> m_white;  // none: the image's largest scaled luminance
};

namespace {
TypeSpec reinhard_spec() {
    TypeSpec s("Reinhard et al. 2002 photographic operator, global version");
    s.add("key", ParamKind::number, "the scaled log-average luminance (> 0)").defaults("0.18").at_least(0);
    s.add("white", ParamKind::number,
          "the smallest scaled luminance shown as white (default: the image maximum; 0: infinite)")
        .at_least(0);
    return s;
}
}  // namespace

void register_reinhard(ToneRegistry& r) {
    r.add(
        "reinhard",
        [](const Params& p) {
            return std::make_shared<ReinhardOperator>(
                p.get_float("key", 0.18f), p.has("white") ? std::optional<double>(p.get_float("white")) : std::nullopt);
        },
        reinhard_spec());
}

}  // namespace rtlab::tonemap
