#pragma once
// The frame every global operator shares: measure, map each finite pixel, write invalid ones black,
// clamp to [0, 1] (private to the tonemap library).
#include <rtlab/tonemap/tone_operator.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <string>

namespace rtlab::tonemap {

// A parameter read as a float, as written ("0.18", not "0.18000000715255737"): its shortest text.
inline std::string shortest(float v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return {buffer, result.ptr};
}

// A measured value to six significant digits (printf's %.6g).
inline std::string six_digits(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return buffer;
}

template <class MapPixel>
Image map_pixels(const Image& hdr, MapPixel&& map) {
    Image out(hdr.width(), hdr.height());
    auto src = hdr.pixels();
    auto dst = out.pixels();
    for (std::size_t i = 0; i < src.size(); ++i) {
        const RGB& p = src[i];
        if (!p.is_finite()) continue;  // stays black; counted by measure_luminance
        const RGB c(std::max(p.r, 0.0f), std::max(p.g, 0.0f), std::max(p.b, 0.0f));
        RGB m = map(c);
        if (!m.is_finite()) m = RGB(1.0f);  // only reachable through overflow of a huge input
        dst[i] = RGB(std::clamp(m.r, 0.0f, 1.0f), std::clamp(m.g, 0.0f, 1.0f), std::clamp(m.b, 0.0f, 1.0f));
    }
    return out;
}

inline void fill_report(ToneReport* report, const LuminanceStats& s, double scale, std::string summary) {
    if (!report) return;
    report->log_average = s.log_average;
    report->max_luminance = s.max_luminance;
    report->invalid_pixels = s.invalid_pixels;
    report->scale = scale;
    report->summary = std::move(summary);
}

}  // namespace rtlab::tonemap
