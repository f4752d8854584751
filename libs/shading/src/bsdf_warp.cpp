// The warps the built-in lobes sample with (bsdf.hpp).
#include <rtlab/core/frame.hpp>
#include <rtlab/shading/bsdf.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

Vec3 sample_cosine_hemisphere(const Vec2& u) {
    // Concentric map of the square onto the disk: equal areas stay equal, and neighbours stay neighbours.
    const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    float r = 0.0f, phi = 0.0f;
    if (a != 0.0f || b != 0.0f) {
        if (std::abs(a) > std::abs(b)) {
            r = a;
            phi = 0.25f * kPi * (b / a);
        } else {
            r = b;
            phi = 0.5f * kPi - 0.25f * kPi * (a / b);
        }
    }
    const float x = r * std::cos(phi), y = r * std::sin(phi);
    return {x, y, std::sqrt(std::max(0.0f, 1.0f - x * x - y * y))};
}

Vec3 sample_power_cosine(const Vec3& axis, float exponent, const Vec2& u) {
    // CDF of cos(alpha) = c: 1 - c^(e + 1), so c = (1 - u)^(1 / (e + 1)).
    const float one_minus_cos = -std::expm1(std::log1p(-u.x) / (exponent + 1.0f));
    const float cos_a = 1.0f - one_minus_cos;
    const float sin_a = std::sqrt(std::max(0.0f, one_minus_cos * (1.0f + cos_a)));
    const float phi = 2.0f * kPi * u.y;
    const Frame frame = Frame::from_normal(axis);
    return glm::normalize(frame.to_world(Vec3(sin_a * std::cos(phi), sin_a * std::sin(phi), cos_a)));
}

}  // namespace rtlab
