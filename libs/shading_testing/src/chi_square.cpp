// The chi-square goodness-of-fit test of a direction sampler against its density.
#include <rtlab/shading_testing/chi_square.hpp>
#include <rtlab/shading_testing/sphere_quadrature.hpp>
#include <rtlab/shading_testing/statistics.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

namespace rtlab::shading_testing {

void chi_square_from_counts(const std::vector<double>& observed, const std::vector<double>& expected,
                            ChiSquareResult& result, const std::function<std::string(int)>& names) {
    std::vector<std::pair<double, double>> bins;  // (observed, expected)
    double pool_o = 0.0, pool_e = 0.0, worst = 0.0;
    for (int b = 0; b < static_cast<int>(expected.size()); ++b) {
        if (expected[b] < 5.0) {
            pool_o += observed[b];
            pool_e += expected[b];
            continue;
        }
        const double term = (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
        if (term > worst) {
            worst = term;
            std::ostringstream m;
            m << (names ? names(b) : "bin " + std::to_string(b)) << ": observed " << observed[b] << " expected "
              << expected[b];
            result.worst = m.str();
        }
        bins.emplace_back(observed[b], expected[b]);
    }
    if (pool_e >= 5.0) {
        bins.emplace_back(pool_o, pool_e);
    } else if (pool_e > 0.0 || pool_o > 0.0) {
        if (bins.empty()) {
            bins.emplace_back(pool_o, pool_e);
        } else {
            auto smallest = std::min_element(bins.begin(), bins.end(),
                                             [](const auto& x, const auto& y) { return x.second < y.second; });
            smallest->first += pool_o;
            smallest->second += pool_e;
        }
    }
    result.statistic = 0.0;
    for (const auto& [o, e] : bins) result.statistic += (o - e) * (o - e) / e;
    result.dof = static_cast<int>(bins.size()) - 1;
    result.p_value = result.dof > 0 ? chi_square_survival(result.statistic, result.dof) : 1.0;
}

ChiSquareResult chi_square_test(const std::function<std::optional<Vec3>(Rng&)>& sample,
                                const std::function<double(const Vec3&)>& pdf, const std::vector<Vec3>& hints, Rng& rng,
                                int n, ChiSquareSettings settings) {
    ChiSquareResult result;
    const int n_c = settings.n_c, n_phi = settings.n_phi, cells = n_c * n_phi;
    std::vector<double> observed(cells + 1, 0.0), expected(cells + 1, 0.0);
    for (int k = 0; k < n; ++k) {
        const std::optional<Vec3> w = sample(rng);
        if (!w) {
            observed[cells] += 1.0;
            ++result.samples_outside;
            continue;
        }
        const double c = std::clamp(double(w->z), -1.0, 1.0);
        double phi = std::atan2(double(w->y), double(w->x));
        if (phi < 0.0) phi += 2.0 * std::numbers::pi;
        const int i = std::clamp(static_cast<int>((c + 1.0) * 0.5 * n_c), 0, n_c - 1);
        const int j = std::clamp(static_cast<int>(phi / (2.0 * std::numbers::pi) * n_phi), 0, n_phi - 1);
        observed[i * n_phi + j] += 1.0;
    }
    const SphereQuadrature quadrature(pdf, hints, settings.tolerance > 0.0 ? settings.tolerance : 0.01 / n,
                                      settings.relative_tolerance > 0.0 ? settings.relative_tolerance : 1.0 / n);
    double total = 0.0;
    for (int i = 0; i < n_c; ++i)
        for (int j = 0; j < n_phi; ++j) {
            const double p =
                quadrature.integrate(-1.0 + 2.0 * i / n_c, -1.0 + 2.0 * (i + 1) / n_c,
                                     2.0 * std::numbers::pi * j / n_phi, 2.0 * std::numbers::pi * (j + 1) / n_phi);
            expected[i * n_phi + j] = p * n;
            total += p;
        }
    result.pdf_integral = total;
    expected[cells] = std::max(0.0, 1.0 - total) * n;
    const auto name = [&](int b) {
        return b == cells ? std::string("lost or delta draws")
                          : "cell c " + std::to_string(b / n_phi) + " phi " + std::to_string(b % n_phi);
    };

    // A draw where the density integrates to (nearly) nothing: the sampler and pdf disagree outright.
    for (int b = 0; b <= cells; ++b)
        if (observed[b] > 0.0 && expected[b] < 1e-4) {
            std::ostringstream m;
            m << name(b) << ": " << observed[b] << " draws, " << expected[b] << " expected";
            result.failure = m.str();
            result.p_value = 0.0;
            return result;
        }
    chi_square_from_counts(observed, expected, result, name);
    return result;
}

}  // namespace rtlab::shading_testing
