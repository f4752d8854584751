// exposure: a linear scale by 2^stops, then clamping (the reference the others are compared with).
// aces: Narkowicz's 2015 fit of the ACES filmic curve, f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14),
// applied per channel after the same 2^stops exposure. Parameter of both: stops (default 0).
#include <rtlab/core/error.hpp>

#include "global_operator.hpp"

#include <fmt/core.h>
#include <cmath>

namespace rtlab::tonemap {

namespace {
float aces_fit(float x) { return x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f); }
}  // namespace

class ExposureOperator final : public ToneOperator {
public:
    ExposureOperator(double stops, bool filmic) : m_stops(stops), m_filmic(filmic) {
        if (!std::isfinite(stops) || std::abs(stops) > 64.0)
            throw Error(std::string("tone operator '") + (filmic ? "aces" : "exposure") +
                        "': stops must lie in [-64, 64]");
    }
    Image apply(const Image& hdr, ToneReport* report) const override {
        const double scale = std::exp2(m_stops);
        // The parameter was read as a float: printed as one ("0.18", not "0.18000000715255737").
        fill_report(report, measure_luminance(hdr), scale,
                    fmt::format("{}: {} stops, scale {:.6g}", m_filmic ? "aces" : "exposure",
                                static_cast<float>(m_stops), scale));
        const auto s = static_cast<float>(scale);
        if (!m_filmic) return map_pixels(hdr, [s](const RGB& c) { return c * s; });
        return map_pixels(hdr, [s](const RGB& c) {
            const RGB x = c * s;
            // For huge x the fit tends to 2.51 / 2.43 > 1; the clamp in map_pixels makes it 1.
            return RGB(aces_fit(std::min(x.r, 1e18f)), aces_fit(std::min(x.g, 1e18f)), aces_fit(std::min(x.b, 1e18f)));
        });
    }

private:
    double m_stops;
    bool m_filmic;
};

namespace {
TypeSpec stops_spec(std::string doc) {
    TypeSpec s(std::move(doc));
    s.add("stops", ParamKind::number, "exposure: each stop doubles the light").defaults("0").range(-64, 64).in("stops");
    return s;
}
}  // namespace

void register_exposure(ToneRegistry& r) {
    r.add(
        "exposure",
        [](const Params& p) { return std::make_shared<ExposureOperator>(p.get_float("stops", 0.0f), false); },
        stops_spec("linear scale by 2^stops, clamped"));
    r.add(
        "aces", [](const Params& p) { return std::make_shared<ExposureOperator>(p.get_float("stops", 0.0f), true); },
        stops_spec("Narkowicz 2015 ACES filmic fit per channel after 2^stops"));
}

}  // namespace rtlab::tonemap
