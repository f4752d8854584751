#pragma once
/// \brief Linear RGB colour (or radiance) with component-wise arithmetic.
#include <algorithm>
#include <cmath>

namespace rtlab {

/// \brief Linear RGB triple; values may exceed 1 (HDR).
struct RGB {
    float r = 0.0f, g = 0.0f, b = 0.0f;

    constexpr RGB() = default;
    constexpr RGB(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit RGB(float v) : r(v), g(v), b(v) {}

    constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    constexpr RGB& operator+=(const RGB& o) {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    constexpr RGB& operator*=(const RGB& o) {
        r *= o.r;
        g *= o.g;
        b *= o.b;
        return *this;
    }
    constexpr RGB& operator*=(float s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    constexpr RGB& operator/=(float s) { return *this *= (1.0f / s); }
    friend constexpr RGB operator+(RGB a, const RGB& b) { return a += b; }
    friend constexpr RGB operator-(const RGB& a, const RGB& b) { return {a.r - b.r, a.g - b.g, a.b - b.b}; }
    friend constexpr RGB operator*(RGB a, const RGB& b) { return a *= b; }
    friend constexpr RGB operator*(RGB a, float s) { return a *= s; }
    friend constexpr RGB operator*(float s, RGB a) { return a *= s; }
    friend constexpr RGB operator/(RGB a, float s) { return a /= s; }
    friend constexpr bool operator==(const RGB&, const RGB&) = default;

    constexpr bool is_black() const { return r == 0.0f && g == 0.0f && b == 0.0f; }
    bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
    constexpr float max_component() const { return std::max(r, std::max(g, b)); }
    /// Relative luminance from linear Rec. 709 / sRGB primaries.
    constexpr float luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
};

/// Linear interpolation (1 - t) a + t b.
constexpr RGB lerp(const RGB& a, const RGB& b, float t) { return a * (1.0f - t) + b * t; }

}  // namespace rtlab
