#pragma once
// Checks of an EnvironmentMap's sampling, shared by the shading tests (synthetic maps) and the render tests (the
// studio maps of blender-data, which only render reads): the map's orientation as documented, written here
// independently of the library; a chi-square test of sample_li's directions against pdf_li on the map's own
// half-texel cells (on which pdf_li times the area element is constant, so the expected counts are exact); the
// integral of pdf_li over the sphere; and a deterministic quadrature of the light a diffuse surface reflects.
#include <rtlab/core/cube_face.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/environment_map.hpp>

#include <rtlab/shading_testing/chi_square.hpp>
#include <rtlab/shading_testing/statistics.hpp>

#include "sample_scale.hpp"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace rtlab::test {

using shading_testing::ChiSquareResult;
using shading_testing::sidak_level;

/// The chi-square of histogram counts against exact expected counts; a bin with draws where (nearly) none are
/// expected fails outright (p 0, `failure` names it).
inline ChiSquareResult chi_square_counts(const std::vector<double>& observed, const std::vector<double>& expected,
                                         const std::function<std::string(int)>& name) {
    ChiSquareResult result;
    for (std::size_t b = 0; b < observed.size(); ++b)
        if (observed[b] > 0.0 && expected[b] < 1e-4) {
            result.failure = name(static_cast<int>(b)) + ": " + std::to_string(observed[b]) + " draws, " +
                             std::to_string(expected[b]) + " expected";
            result.p_value = 0.0;
            return result;
        }
    shading_testing::chi_square_from_counts(observed, expected, result, name);
    return result;
}

inline constexpr double kPiD = std::numbers::pi;

/// The world direction of an equirectangular map's (u, v) (v = 0 up) turned by `degrees` about +y, by the
/// documented orientation: u = 0.5 faces +x, u = 0.75 faces +z; turning by the right-hand rule.
inline glm::dvec3 equirect_direction(double u, double v, double degrees) {
    const double theta = kPiD * v, phi = 2.0 * kPiD * (u - 0.5);
    const glm::dvec3 l(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    const double a = degrees * kPiD / 180.0, c = std::cos(a), s = std::sin(a);
    return {c * l.x + s * l.z, l.y, c * l.z - s * l.x};
}

/// The map's (u, v) of a world direction: the inverse of equirect_direction.
inline glm::dvec2 equirect_uv(const glm::dvec3& w, double degrees) {
    const glm::dvec3 d = glm::normalize(w);
    const double a = degrees * kPiD / 180.0, c = std::cos(a), s = std::sin(a);
    const glm::dvec3 l(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
    double u = 0.5 + std::atan2(l.z, l.x) / (2.0 * kPiD);
    if (u >= 1.0) u -= 1.0;
    return {u, std::acos(std::clamp(l.y, -1.0, 1.0)) / kPiD};
}

/// A cube map's face coordinates in world space turned by `degrees` (core's cube-face convention).
inline glm::dvec3 cube_direction(CubeFace face, double s, double t, double degrees) {
    const glm::dvec3 l = glm::normalize(glm::dvec3(cube_face_direction(face, float(s), float(t))));
    const double a = degrees * kPiD / 180.0, c = std::cos(a), sn = std::sin(a);
    return {c * l.x + sn * l.z, l.y, c * l.z - sn * l.x};
}

/// The outcome of check_environment_sampling.
struct EnvironmentSamplingResult {
    ChiSquareResult chi2;
    double pdf_integral = 0.0;    // of pdf_li over the sphere, by Gauss-Legendre in theta per cell
    int pdf_mismatches = 0;       // samples whose pdf differs from pdf_li at their direction by over 1e-3
    int radiance_mismatches = 0;  // samples whose radiance differs from radiance() at their direction
    int lost = 0;                 // sample_li gave nothing
};

/// A map of nu x nv sampling cells (its distribution's), binned in groups of bu x bv cells: n directions from
/// sample_li against pdf_li. For a cube map the bins are per face.
inline EnvironmentSamplingResult check_environment_sampling(const EnvironmentMap& map, Rng& rng, int n, int bu,
                                                            int bv) {
    EnvironmentSamplingResult result;
    const Distribution2D& dist = map.distribution();
    const int nu = static_cast<int>(dist.columns()), nv = static_cast<int>(dist.rows());
    const double degrees = map.options().rotation_degrees;
    const bool cube = map.is_cube();
    const int bins_u = nu / bu, bins_v = nv / bv;
    // A cell's (u, v) over [0, 1)^2 and back: equirectangular directly; cube maps stack six faces of nu x nu.
    auto direction_of = [&](double u, double v) {
        if (!cube) return equirect_direction(u, v, degrees);
        const int face = std::min(5, static_cast<int>(v * 6.0));
        return cube_direction(static_cast<CubeFace>(face), u, v * 6.0 - face, degrees);
    };
    // Solid angle per unit area of [0, 1)^2 at (u, v).
    auto jacobian = [&](double u, double v) {
        if (!cube) return 2.0 * kPiD * kPiD * std::sin(kPiD * v);
        const int face = std::min(5, static_cast<int>(v * 6.0));
        const double sc = 2.0 * u - 1.0, tc = 2.0 * (v * 6.0 - face) - 1.0;
        return 24.0 / std::pow(1.0 + sc * sc + tc * tc, 1.5);
    };
    auto bin_of = [&](const glm::dvec3& w) {
        double u = 0.0, v = 0.0;
        if (!cube) {
            const glm::dvec2 uv = equirect_uv(w, degrees);
            u = uv.x, v = uv.y;
        } else {
            const double a = -degrees * kPiD / 180.0, c = std::cos(a), s = std::sin(a);
            const glm::dvec3 l(c * w.x + s * w.z, w.y, c * w.z - s * w.x);
            const CubeFaceCoord f = cube_face_coord(Vec3(l));
            u = f.s, v = (static_cast<int>(f.face) + std::min(double(f.t), 1.0 - 1e-9)) / 6.0;
        }
        const int i = std::clamp(static_cast<int>(u * nu), 0, nu - 1),
                  j = std::clamp(static_cast<int>(v * nv), 0, nv - 1);
        return (j / bv) * bins_u + i / bu;
    };

    std::vector<double> observed(bins_u * bins_v + 1, 0.0), expected(bins_u * bins_v + 1, 0.0);
    for (int k = 0; k < n; ++k) {
        const auto s = map.sample_li(Point3(0.0f), rng.uniform2());
        if (!s) {
            ++result.lost;
            observed.back() += 1.0;
            continue;
        }
        const float pdf = map.pdf_li(Point3(0.0f), s->wi, Point3(0.0f), s->wi);
        if (std::abs(pdf - s->pdf) > 1e-3f * s->pdf) ++result.pdf_mismatches;
        const RGB le = map.radiance(s->wi);
        if (std::abs(le.r - s->radiance.r) > 1e-3f * std::max(1e-3f, le.r)) ++result.radiance_mismatches;
        observed[bin_of(glm::dvec3(s->wi))] += 1.0;
    }
    // Expected: pdf_li at each cell's centre times the cell's solid angle (pdf_li times the Jacobian is the
    // distribution's constant on the cell); the integral over the sphere by 2-point Gauss-Legendre across each
    // cell (in theta for equirectangular maps), with the textbook area element.
    static constexpr double kX[2] = {-0.5773502691896257, 0.5773502691896257};
    static constexpr double kW[2] = {1.0, 1.0};
    double total = 0.0, integral = 0.0;
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const double u = (i + 0.5) / nu, v = (j + 0.5) / nv;
            const glm::dvec3 w = direction_of(u, v);
            const double pdf = map.pdf_li(Point3(0.0f), Vec3(w), Point3(0.0f), Vec3(w));
            const double mass = pdf * jacobian(u, v) / (double(nu) * nv);
            expected[(j / bv) * bins_u + i / bu] += mass * n;
            total += mass;
            for (int a = 0; a < 2; ++a) {
                const double va = (j + 0.5 + 0.5 * kX[a]) / nv;
                const glm::dvec3 wa = direction_of(u, va);
                const double pa = map.pdf_li(Point3(0.0f), Vec3(wa), Point3(0.0f), Vec3(wa));
                // d omega per du dv by the textbook: equirectangular 2 pi^2 sin(theta); a cube face's 4 / r^3,
                // times 6 for the stacking.
                integral += 0.5 * kW[a] * pa * jacobian(u, va) / (double(nu) * nv);
            }
        }
    result.pdf_integral = integral;
    expected.back() = std::max(0.0, 1.0 - total) * n;
    result.chi2 = chi_square_counts(observed, expected, [&](int b) {
        if (b == bins_u * bins_v) return std::string("lost");
        return "bin u " + std::to_string(b % bins_u) + " v " + std::to_string(b / bins_u);
    });
    return result;
}

/// The light a Lambert surface of albedo 1 with unit normal n reflects under the map, (1 / pi) times the integral
/// of radiance(w) max(0, n . w) over the sphere, deterministically: 2 x 2 Gauss-Legendre points on each sampling
/// cell (half a texel), where the bilinear lookup is smooth. Green channel.
inline double reflected_by_quadrature(const EnvironmentMap& map, const glm::dvec3& n) {
    const Distribution2D& dist = map.distribution();
    const int nu = static_cast<int>(dist.columns()), nv = static_cast<int>(dist.rows());
    const double degrees = map.options().rotation_degrees;
    static constexpr double kX[2] = {-0.5773502691896257, 0.5773502691896257};
    double sum = 0.0;
    if (!map.is_cube()) {
        for (int j = 0; j < nv; ++j) {
            double row = 0.0;
            for (int b = 0; b < 2; ++b) {
                const double v = (j + 0.5 + 0.5 * kX[b]) / nv;
                const double weight = std::sin(kPiD * v);
                for (int i = 0; i < nu; ++i)
                    for (int a = 0; a < 2; ++a) {
                        const glm::dvec3 w = equirect_direction((i + 0.5 + 0.5 * kX[a]) / nu, v, degrees);
                        const double c = glm::dot(w, n);
                        if (c > 0.0) row += map.radiance(Vec3(w)).g * c * weight;
                    }
            }
            sum += row;
        }
        // Each point stands for a quarter of a cell: d u d v / 4 with d omega = 2 pi^2 sin(theta) du dv.
        return sum * 2.0 * kPiD * kPiD / (4.0 * nu * nv) / kPiD;
    }
    const int side = nu;
    for (int f = 0; f < 6; ++f)
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i)
                for (int b = 0; b < 2; ++b)
                    for (int a = 0; a < 2; ++a) {
                        const double s = (i + 0.5 + 0.5 * kX[a]) / side, t = (j + 0.5 + 0.5 * kX[b]) / side;
                        const glm::dvec3 w = cube_direction(static_cast<CubeFace>(f), s, t, degrees);
                        const double c = glm::dot(w, n);
                        const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
                        if (c > 0.0) sum += map.radiance(Vec3(w)).g * c * 4.0 / std::pow(1.0 + sc * sc + tc * tc, 1.5);
                    }
    return sum / (4.0 * side * side) / kPiD;
}

}  // namespace rtlab::test
