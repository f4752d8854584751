// ward: Ward's 1994 contrast-based scale factor ("A contrast-based scalefactor for luminance display").
//   m = [(1.219 + L_da^0.4) / (1.219 + L_wa^0.4)]^2.5 / L_dmax,  display = m * world RGB
// with L_wa the log-average world luminance and L_da = L_dmax / 2 the display adaptation luminance.
// Parameters: ldmax (display maximum, cd/m^2, default 100).
#include <rtlab/core/error.hpp>

#include "global_operator.hpp"

#include <fmt/core.h>
#include <cmath>

namespace rtlab::tonemap {

class WardOperator final : public ToneOperator {
public:
    explicit WardOperator(double ld_max) : m_ld_max(ld_max) {
        if (!(ld_max > 0.0 && std::isfinite(ld_max))) throw Error("tone operator 'ward': ldmax must be positive");
    }
    Image apply(const Image& hdr, ToneReport* report) const override {
        const LuminanceStats s = measure_luminance(hdr);
        const double ld_a = m_ld_max / 2.0;
        const double m =
            std::pow((1.219 + std::pow(ld_a, 0.4)) / (1.219 + std::pow(s.log_average, 0.4)), 2.5) / m_ld_max;
        // The parameter was read as a float: printed as one ("0.18", not "0.18000000715255737").
        fill_report(
            report, s, m,
            fmt::format("ward: ldmax {} cd/m2, L_wa {:.6g}, m {:.6g}", static_cast<float>(m_ld_max), s.log_average, m));
        const auto mf = static_cast<float>(m);
        return map_pixels(hdr, [mf](const RGB& c) { return c * mf; });
    }

private:
    double m_ld_max;
};

namespace {
TypeSpec ward_spec() {
    TypeSpec s("Ward 1994 contrast-based scale factor");
    s.add("ldmax", ParamKind::number, "the display's maximum luminance (> 0)").defaults("100").at_least(0).in("cd/m2");
    return s;
}
}  // namespace

void register_ward(ToneRegistry& r) {
    r.add(
        "ward", [](const Params& p) { return std::make_shared<WardOperator>(p.get_float("ldmax", 100.0f)); },
        ward_spec());
}

}  // namespace rtlab::tonemap
