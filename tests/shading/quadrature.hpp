#pragma once
// Deterministic quadrature over directions for the BRDF tests: midpoint rules, so every figure is
// reproducible and its error shrinks predictably as the grid is refined.
#include <rtlab/core/math.hpp>
#include <rtlab/shading/brdf.hpp>

#include <cmath>
#include <type_traits>
#include <vector>

namespace rtlab::test {

/// The integral of g(w) over the upper hemisphere, midpoint rule on a theta x phi grid.
template <class G>
double integrate_hemisphere(G&& g, int n_theta = 256, int n_phi = 512) {
    const double d_theta = 0.5 * std::numbers::pi / n_theta, d_phi = 2.0 * std::numbers::pi / n_phi;
    double sum = 0.0;
    for (int i = 0; i < n_theta; ++i) {
        const double theta = (i + 0.5) * d_theta;
        const double st = std::sin(theta), ct = std::cos(theta);
        double ring = 0.0;
        for (int j = 0; j < n_phi; ++j) {
            const double phi = (j + 0.5) * d_phi;
            ring += g(Vec3(static_cast<float>(st * std::cos(phi)), static_cast<float>(st * std::sin(phi)),
                           static_cast<float>(ct)));
        }
        sum += ring * st;
    }
    return sum * d_theta * d_phi;
}

/// The integral of g(w) over the directions within theta_max of the unit `axis`, in polar coordinates about
/// it with theta = theta_max u^2 on a midpoint grid in u: rings crowd near the axis, so a lobe 1e-4 rad
/// wide around it is resolved. g must vanish where it should (below the surface, say).
/// g returns a double or a glm::dvec3 (three channels at once).
template <class G>
auto integrate_about(G&& g, const Vec3& axis, double theta_max, int n_u = 1024, int n_phi = 512) {
    using T = std::decay_t<decltype(g(axis))>;
    // An orthonormal frame (t, b, axis).
    const Vec3 helper = std::abs(axis.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 t = glm::normalize(glm::cross(helper, axis));
    const Vec3 b = glm::cross(axis, t);
    std::vector<double> cos_phi(n_phi), sin_phi(n_phi);
    const double du = 1.0 / n_u, d_phi = 2.0 * std::numbers::pi / n_phi;
    for (int j = 0; j < n_phi; ++j) {
        cos_phi[j] = std::cos((j + 0.5) * d_phi);
        sin_phi[j] = std::sin((j + 0.5) * d_phi);
    }
    T sum{};
    for (int i = 0; i < n_u; ++i) {
        const double u = (i + 0.5) * du;
        const double theta = theta_max * u * u;
        const double st = std::sin(theta), ct = std::cos(theta);
        T ring{};
        for (int j = 0; j < n_phi; ++j) {
            const Vec3 w = static_cast<float>(st * cos_phi[j]) * t + static_cast<float>(st * sin_phi[j]) * b +
                           static_cast<float>(ct) * axis;
            ring += g(w);
        }
        sum += ring * (st * 2.0 * theta_max * u);  // d theta = 2 theta_max u du
    }
    return sum * du * d_phi;
}

/// Directional albedo per channel: the integral of f(wo, wi) cos(theta_i) over wi, written over half
/// vectors h (wi = 2 (wo.h) h - wo, d wi = 4 (wo.h) d h) on the grid about the normal. Every lobe here is
/// centred on h = n, so a near-mirror lobe is resolved however grazing wo is, where in wi it is squashed
/// into a sliver beside the horizon.
inline glm::dvec3 albedo_rgb(const Brdf& f, const Vec3& wo, int n_u = 1024, int n_phi = 512) {
    const auto g = [&](const Vec3& h) {
        const float cos_d = glm::dot(wo, h);
        if (!(cos_d > 0.0f)) return glm::dvec3(0.0);
        const Vec3 wi = 2.0f * cos_d * h - wo;
        if (!(wi.z > 0.0f)) return glm::dvec3(0.0);
        const RGB v = f.eval(wo, wi);
        return glm::dvec3(v.r, v.g, v.b) * (static_cast<double>(wi.z) * 4.0 * cos_d);
    };
    return integrate_about(g, Vec3(0, 0, 1), 0.5 * std::numbers::pi, n_u, n_phi);
}

/// The green channel of albedo_rgb.
inline double albedo(const Brdf& f, const Vec3& wo, int n_u = 1024, int n_phi = 512) {
    return albedo_rgb(f, wo, n_u, n_phi).y;
}

/// A unit direction at polar angle theta from +z and azimuth phi.
inline Vec3 direction(float theta, float phi = 0.0f) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

}  // namespace rtlab::test
