// The distributions behind the goodness-of-fit tests, in double.
#include <rtlab/shading_testing/statistics.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab::shading_testing {

namespace {

/// P by its power series below x = a + 1, Q by its continued fraction (evaluated by the modified Lentz method)
/// above, where each converges quickly; `upper` says which one to return.
double regularised_gamma(double a, double x, bool upper) {
    if (!(x > 0.0)) return upper ? 1.0 : 0.0;
    const double log_prefix = -x + a * std::log(x) - std::lgamma(a);
    constexpr double kEps = 1e-15;
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 100000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * kEps) break;
        }
        const double p = std::min(1.0, sum * std::exp(log_prefix));
        return upper ? 1.0 - p : p;
    }
    constexpr double kTiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < kEps) break;
    }
    const double q = std::min(1.0, std::exp(log_prefix) * h);
    return upper ? q : 1.0 - q;
}

}  // namespace

double regularised_gamma_p(double a, double x) { return regularised_gamma(a, x, false); }
double regularised_gamma_q(double a, double x) { return regularised_gamma(a, x, true); }

double chi_square_survival(double statistic, int dof) { return regularised_gamma_q(0.5 * dof, 0.5 * statistic); }

double binomial_p_value(int k, int n, double p) {
    if (p <= 0.0) return k == 0 ? 1.0 : 0.0;
    if (p >= 1.0) return k == n ? 1.0 : 0.0;
    auto log_pmf = [&](int i) {
        return std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + i * std::log(p) +
               (n - i) * std::log1p(-p);
    };
    double lower = 0.0, upper = 0.0;
    for (int i = 0; i <= k; ++i) lower += std::exp(log_pmf(i));
    for (int i = k; i <= n; ++i) upper += std::exp(log_pmf(i));
    return std::min(1.0, 2.0 * std::min(lower, upper));
}

double sidak_level(double family_alpha, int tests) { return 1.0 - std::pow(1.0 - family_alpha, 1.0 / tests); }

}  // namespace rtlab::shading_testing
