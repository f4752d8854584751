#include <rtlab/tonemap/tone_operator.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

LuminanceStats measure_luminance(const Image& hdr, double delta) {
    LuminanceStats s;
    double log_sum = 0.0;
    std::size_t valid = 0;
    for (const RGB& p : hdr.pixels()) {
        if (!p.is_finite()) {
            ++s.invalid_pixels;
            continue;
        }
        const RGB c(std::max(p.r, 0.0f), std::max(p.g, 0.0f), std::max(p.b, 0.0f));
        const double l = c.luminance();
        log_sum += std::log(delta + l);
        s.max_luminance = std::max(s.max_luminance, l);
        ++valid;
    }
    s.log_average = valid > 0 ? std::exp(log_sum / static_cast<double>(valid)) : delta;
    return s;
}

}  // namespace rtlab
