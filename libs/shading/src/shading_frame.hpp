#pragma once
// The local shading frame every integrator shades in (private to the shading library).
#include <rtlab/core/color.hpp>
#include <rtlab/core/frame.hpp>

#include <cmath>

namespace rtlab::shading_detail {

// The shading frame: the shading normal, and the surface tangent as local +x (anisotropic models need it).
inline Frame shading_frame(const Normal3& n, const Vec3& tangent) {
    Vec3 s = tangent - glm::dot(tangent, n) * n;
    const float len = glm::length(s);
    if (!(len > 1e-6f) || !std::isfinite(len)) return Frame::from_normal(n);
    s /= len;
    return Frame{s, glm::cross(n, s), n};
}

inline RGB exp_rgb(const RGB& c) { return {std::exp(c.r), std::exp(c.g), std::exp(c.b)}; }

}  // namespace rtlab::shading_detail
