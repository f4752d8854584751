#pragma once
/// \brief Chi-square goodness of fit of a direction sampler against its density (the method of Nori's warptest
/// and Mitsuba 3's chi2 module): a (cos theta, phi) histogram of draws against the density integrated over each
/// cell by adaptive quadrature, low-count cells pooled.
#include <rtlab/core/math.hpp>
#include <rtlab/core/rng.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::shading_testing {

/// The outcome of a chi-square goodness-of-fit test.
struct ChiSquareResult {
    double statistic = 0.0;
    int dof = 0;
    double p_value = 1.0;
    double pdf_integral = 0.0;  ///< the density's integral over the sphere
    int samples_outside = 0;    ///< draws the density does not describe (lost, or delta lobes)
    std::string failure;        ///< a draw where the density says none can be: its cell (the p-value is then 0)
    std::string worst;          ///< the bin that adds most to the statistic, for the report
};

/// The statistic of observed against expected counts, bin by bin: bins expected below 5 are pooled, and a pool
/// still below 5 joins the smallest other bin. Fills statistic, dof and p_value; `names` (optional, one a bin)
/// name the worst bin in `worst`.
void chi_square_from_counts(const std::vector<double>& observed, const std::vector<double>& expected,
                            ChiSquareResult& result, const std::function<std::string(int)>& names = {});

/// The histogram and its expected counts.
struct ChiSquareSettings {
    /// The grid: n_c bands of cos theta in [-1, 1] by n_phi sectors of phi in [0, 2 pi).
    int n_c = 24, n_phi = 24;
    /// The quadrature's tolerance in each cell, of the density's integral: absolute, or relative to the cell's
    /// integral. 0: 0.01 / n and 1 / n, so that no cell's expected count errs by more than a hundredth of a
    /// draw or a thousandth of its standard deviation, and fewer draws cost less quadrature too.
    double tolerance = 0.0, relative_tolerance = 0.0;
};

/// \brief Draws n directions from `sample` (nullopt: lost, or a delta lobe the density does not cover),
/// histograms them on the grid, and compares with the expected counts n * (the integral of pdf over each
/// cell, by SphereQuadrature with the given hints, rtlab/shading_testing/sphere_quadrature.hpp); the draws outside the
/// density get one more bin, expected n (1 - integral of pdf).
ChiSquareResult chi_square_test(const std::function<std::optional<Vec3>(Rng&)>& sample,
                                const std::function<double(const Vec3&)>& pdf, const std::vector<Vec3>& hints, Rng& rng,
                                int n, ChiSquareSettings settings = {});

}  // namespace rtlab::shading_testing
