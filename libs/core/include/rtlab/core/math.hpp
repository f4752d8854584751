#pragma once
/// \brief Vector naming on top of GLM, and the few numeric helpers every library needs.
#include <glm/glm.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace rtlab {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
/// Points and normals are plain vectors; the names say which is meant where it matters.
using Point2 = glm::vec2;
using Point3 = glm::vec3;
using Normal3 = glm::vec3;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = std::numbers::inv_pi_v<float>;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

/// gamma(n) of Pharr et al.: a bound on the relative error of n chained float operations.
constexpr float gamma_bound(int n) {
    constexpr float eps = std::numeric_limits<float>::epsilon() * 0.5f;
    return (static_cast<float>(n) * eps) / (1.0f - static_cast<float>(n) * eps);
}

/// The next float towards +infinity, as std::nextafter(x, +inf) but inline: spawning every secondary ray
/// takes up to three of these, and the library call was 3-4% of a Whitted render. NaN and +inf stay as
/// they are; -0 and +0 both step to the smallest positive subnormal.
inline float next_float_up(float x) {
    if (std::isnan(x) || x == kInfinity) return x;
    if (x == 0.0f) x = 0.0f;  // -0 steps like +0
    std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
    bits = x >= 0.0f ? bits + 1 : bits - 1;  // sign-magnitude: away from zero above it, towards zero below
    return std::bit_cast<float>(bits);
}

/// The next float towards -infinity, as std::nextafter(x, -inf).
inline float next_float_down(float x) { return -next_float_up(-x); }

inline bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline float max_component(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline float min_component(const Vec3& v) { return std::min(v.x, std::min(v.y, v.z)); }

/// Index of the largest component (0, 1 or 2).
inline int max_dimension(const Vec3& v) { return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2); }

}  // namespace rtlab
