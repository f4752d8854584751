#pragma once
// Statistics for the sampled-material tests: the chi-square and binomial distributions (written here, from
// the regularised incomplete gamma function and exact binomial sums), Sidak's correction, an adaptive
// quadrature over (cos theta, phi) rectangles, and a chi-square goodness-of-fit test of a sampler against its
// density in the manner of Nori's warptest and Mitsuba 3's chi2 module.
#include <rtlab/core/math.hpp>
#include <rtlab/core/rng.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::test {

/// Fewer samples under the sanitizers, where every evaluation costs ten times as much; the statistics stay
/// valid (only their power drops).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
inline constexpr int kSampleScale = 5;
#else
inline constexpr int kSampleScale = 1;
#endif

/// The regularised incomplete gamma functions P(a, x) = gamma(a, x) / Gamma(a) and Q = 1 - P, a > 0, x >= 0:
/// P by its power series below x = a + 1, Q by its continued fraction (evaluated by the modified Lentz method)
/// above, where each converges quickly; `upper` says which one to return.
inline double regularised_gamma(double a, double x, bool upper) {
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

inline double regularised_gamma_p(double a, double x) { return regularised_gamma(a, x, false); }
inline double regularised_gamma_q(double a, double x) { return regularised_gamma(a, x, true); }

/// The probability that a chi-square variable with `dof` degrees of freedom exceeds `statistic` (the p-value),
/// 1 - P(dof / 2, statistic / 2), with full relative precision far in the tail.
inline double chi_square_survival(double statistic, int dof) { return regularised_gamma_q(0.5 * dof, 0.5 * statistic); }

/// Two-sided exact binomial test: twice the smaller tail probability of seeing k successes in n trials of
/// probability p, capped at 1.
inline double binomial_p_value(int k, int n, double p) {
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

/// The significance level for each of `tests` independent tests so that all of them pass with probability
/// 1 - family_alpha when every null hypothesis holds (Sidak).
inline double sidak_level(double family_alpha, int tests) { return 1.0 - std::pow(1.0 - family_alpha, 1.0 / tests); }

/// The unit direction with cos(theta) = c and azimuth phi (theta from +z).
inline Vec3 direction_at(double c, double phi) {
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    return {static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)), static_cast<float>(c)};
}

/// \brief Adaptive quadrature of a density over solid angle on a rectangle of (cos theta, phi), where d omega =
/// d cos d phi (no Jacobian). Globally adaptive: each piece is integrated by 5 x 5 Gauss-Legendre on each of
/// its halves (split along its longer side in angle), the difference from the rule on the whole being its
/// error estimate, and the piece with the largest error is split next until the errors sum below the
/// tolerance. A lobe narrower than the first nodes' spacing would fall between them, so pieces holding a
/// "hint" (a direction where a narrow lobe peaks: the mirror and refracted directions) are first split into a
/// mesh graded towards it, down to hint_size radians across: lobes of roughness 1e-3 and exponents of 1e4 are then
/// found, whichever cell they peak in. Likewise pieces whose nodes see both zero and non-zero density (the edge of a
/// lobe's support inside a cell: a rough dielectric's microfacets turn away from the viewer along a curve) are
/// split until below edge_size radians, since a jump hides from the error estimate when no node falls beyond it.
class SphereQuadrature {
public:
    using Density = std::function<double(const Vec3&)>;

    SphereQuadrature(Density f, std::vector<Vec3> hints, double tolerance = 1e-7, double hint_size = 1e-5,
                     double edge_size = 1e-4)
        : m_f(std::move(f)),
          m_hints(std::move(hints)),
          m_tolerance(tolerance),
          m_hint_size(hint_size),
          m_edge_size(edge_size) {}

    double integrate(double c0, double c1, double phi0, double phi1) const {
        std::vector<Piece> done, heap;
        std::vector<Piece> hinted{make_piece({c0, c1, phi0, phi1}, rule({c0, c1, phi0, phi1}).value)};
        long budget = kBudget;
        // First resolve the hints, whatever the error estimates say (they cannot see a lobe between nodes).
        while (!hinted.empty()) {
            const Piece p = hinted.back();
            hinted.pop_back();
            const double size = std::max(theta_extent(p.r), phi_extent(p.r));
            // Graded around the hints: a piece may be at most a quarter of its distance from one across (within
            // kHintReach of it), so a lobe of any width centred there, even one stretched a hundredfold at
            // grazing incidence, is crossed by several nodes.
            const double d = hint_distance(p.r);
            const bool split =
                (d < kHintReach && size > std::max(m_hint_size, kGrading * d)) || (size > m_edge_size && p.mixed);
            if (!split || (budget -= 4) <= 0) {
                heap.push_back(p);
                continue;
            }
            hinted.push_back(make_piece(p.a, p.value_a));
            hinted.push_back(make_piece(p.b, p.value_b));
        }
        const auto by_error = [](const Piece& x, const Piece& y) { return x.error < y.error; };
        std::make_heap(heap.begin(), heap.end(), by_error);
        double value = 0.0, error = 0.0;
        for (int step = 0;; ++step) {
            if (step % 256 == 0) {  // sums kept by updates, summed afresh now and then against drift
                value = error = 0.0;
                for (const Piece& p : heap) {
                    value += p.value;
                    error += p.error;
                }
            }
            if (error <= std::max(m_tolerance, 1e-5 * std::abs(value)) || (budget -= 4) <= 0) return value;
            std::pop_heap(heap.begin(), heap.end(), by_error);
            const Piece worst = heap.back();
            heap.pop_back();
            value -= worst.value;
            error -= worst.error;
            for (const Piece& child : {make_piece(worst.a, worst.value_a), make_piece(worst.b, worst.value_b)}) {
                value += child.value;
                error += child.error;
                heap.push_back(child);
                std::push_heap(heap.begin(), heap.end(), by_error);
            }
        }
    }

    /// The integral over the whole sphere, on a grid of n_c x n_phi starting rectangles.
    double integrate_sphere(int n_c = 8, int n_phi = 16) const {
        double sum = 0.0;
        for (int i = 0; i < n_c; ++i)
            for (int j = 0; j < n_phi; ++j)
                sum += integrate(-1.0 + 2.0 * i / n_c, -1.0 + 2.0 * (i + 1) / n_c, 2.0 * std::numbers::pi * j / n_phi,
                                 2.0 * std::numbers::pi * (j + 1) / n_phi);
        return sum;
    }

private:
    struct Rect {
        double c0, c1, phi0, phi1;
    };
    /// A rectangle, its halves, the rule on each half, and the error estimate.
    struct Piece {
        Rect r, a, b;
        double value_a = 0.0, value_b = 0.0, value = 0.0, error = 0.0;
        bool mixed = false;  // some nodes saw zero density, some did not, and the largest times the area matters
    };
    struct Rule {
        double value = 0.0;
        bool mixed = false;
    };
    static constexpr double kNegligible = 1e-10;  // a probability below which an edge is not worth finding

    Piece make_piece(const Rect& r, double whole) const {
        Piece p{r, r, r};
        if (theta_extent(r) >= phi_extent(r)) {
            p.a.c1 = p.b.c0 = 0.5 * (r.c0 + r.c1);
        } else {
            p.a.phi1 = p.b.phi0 = 0.5 * (r.phi0 + r.phi1);
        }
        const Rule ra = rule(p.a), rb = rule(p.b);
        p.value_a = ra.value;
        p.value_b = rb.value;
        p.mixed = ra.mixed || rb.mixed;
        p.value = p.value_a + p.value_b;
        p.error = std::abs(p.value - whole);
        return p;
    }

    Rule rule(const Rect& r) const {
        // 5-point Gauss-Legendre nodes and weights on [-1, 1].
        static constexpr double kX[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                         0.9061798459386640};
        static constexpr double kW[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                         0.2369268850561891};
        const double hc = 0.5 * (r.c1 - r.c0), mc = 0.5 * (r.c1 + r.c0);
        const double hp = 0.5 * (r.phi1 - r.phi0), mp = 0.5 * (r.phi1 + r.phi0);
        double sum = 0.0, largest = 0.0;
        int zeros = 0;
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j) {
                const double v = m_f(direction_at(mc + hc * kX[i], mp + hp * kX[j]));
                zeros += v == 0.0;
                largest = std::max(largest, v);
                sum += kW[i] * kW[j] * v;
            }
        return {sum * hc * hp, zeros > 0 && zeros < 25 && largest * 4.0 * hc * hp > kNegligible};
    }

    // Angular extents: along theta, and along phi at the widest circle of latitude in the rectangle.
    static double theta_extent(const Rect& r) { return std::acos(std::clamp(r.c0, -1.0, 1.0)) - std::acos(r.c1); }
    static double phi_extent(const Rect& r) {
        const double c_min = (r.c0 <= 0.0 && r.c1 >= 0.0) ? 0.0 : std::min(std::abs(r.c0), std::abs(r.c1));
        return (r.phi1 - r.phi0) * std::sqrt(std::max(0.0, 1.0 - c_min * c_min));
    }

    // The angle from the nearest hint to the rectangle (0 inside it), by clamping the hint's (cos, phi) into it.
    double hint_distance(const Rect& r) const {
        // In double, by atan2 of the cross and dot products: acos of a float dot product could not tell
        // angles below 3e-4 apart, and every piece near a hint would look as if it held it.
        const auto angle = [](const glm::dvec3& a, const glm::dvec3& b) {
            return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
        };
        const auto at = [](double c, double phi) {
            const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
            return glm::dvec3(s * std::cos(phi), s * std::sin(phi), c);
        };
        double best = std::numbers::pi;
        for (const Vec3& hint : m_hints) {
            const glm::dvec3 h = glm::normalize(glm::dvec3(hint));
            const double c = std::clamp(h.z, r.c0, r.c1);
            double phi = std::atan2(h.y, h.x);
            if (phi < 0.0) phi += 2.0 * std::numbers::pi;
            // Either way round in phi.
            best = std::min({best, angle(at(c, std::clamp(phi, r.phi0, r.phi1)), h),
                             angle(at(c, std::clamp(phi - 2.0 * std::numbers::pi, r.phi0, r.phi1)), h)});
        }
        return best;
    }

    // A jump inside a cell would never meet an absolute tolerance; the densities tested are continuous, and
    // the budget keeps a mistaken one from hanging the test.
    static constexpr long kBudget = 40000;      // rules per starting rectangle
    static constexpr double kHintReach = 0.05;  // radians
    static constexpr double kGrading = 0.25;
    Density m_f;
    std::vector<Vec3> m_hints;
    double m_tolerance, m_hint_size, m_edge_size;
};

/// The outcome of a chi-square goodness-of-fit test.
struct ChiSquareResult {
    double statistic = 0.0;
    int dof = 0;
    double p_value = 1.0;
    double pdf_integral = 0.0;  // the density's integral over the sphere
    int samples_outside = 0;    // draws the density does not describe (lost, or delta lobes)
    std::string failure;        // a sample where the density says none can be: its cell
    std::string worst;          // the bin that adds most to the statistic, for the report
};

/// \brief The chi-square goodness of fit of histogram counts against their expected counts: a bin with draws
/// where (nearly) none are expected fails outright (p 0, `failure` names it by `name`); bins expected below 5 are
/// pooled, and a pool still below 5 joins the smallest other bin.
inline ChiSquareResult chi_square_counts(const std::vector<double>& observed, const std::vector<double>& expected,
                                         const std::function<std::string(int)>& name) {
    ChiSquareResult result;
    const int count = static_cast<int>(observed.size());
    // A draw where the density integrates to (nearly) nothing: the sampler and pdf disagree outright.
    for (int b = 0; b < count; ++b)
        if (observed[b] > 0.0 && expected[b] < 1e-4) {
            result.failure =
                name(b) + ": " + std::to_string(observed[b]) + " draws, " + std::to_string(expected[b]) + " expected";
            result.p_value = 0.0;
            return result;
        }
    std::vector<std::pair<double, double>> bins;  // (observed, expected)
    double pool_o = 0.0, pool_e = 0.0, worst = 0.0;
    for (int b = 0; b < count; ++b) {
        if (expected[b] >= 5.0) {
            const double term = (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
            if (term > worst) {
                worst = term;
                result.worst =
                    name(b) + ": observed " + std::to_string(observed[b]) + " expected " + std::to_string(expected[b]);
            }
            bins.emplace_back(observed[b], expected[b]);
        } else {
            pool_o += observed[b];
            pool_e += expected[b];
        }
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
    for (const auto& [o, e] : bins) result.statistic += (o - e) * (o - e) / e;
    result.dof = static_cast<int>(bins.size()) - 1;
    result.p_value = result.dof > 0 ? chi_square_survival(result.statistic, result.dof) : 1.0;
    return result;
}

/// \brief Draws n directions from `sample` (nullopt: lost, or a delta lobe the density does not cover),
/// histograms them on an n_c x n_phi grid of (cos theta in [-1, 1], phi in [0, 2 pi)), and compares with the
/// expected counts n * (integral of pdf over each cell); the draws outside the density get one more bin,
/// expected n (1 - integral of pdf). Bins expected below 5 are pooled; a pool still below 5 joins the
/// smallest other bin.
inline ChiSquareResult chi_square_test(const std::function<std::optional<Vec3>(Rng&)>& sample,
                                       const std::function<double(const Vec3&)>& pdf, const std::vector<Vec3>& hints,
                                       Rng& rng, int n, int n_c = 24, int n_phi = 24) {
    ChiSquareResult result;
    const int cells = n_c * n_phi;
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
    const SphereQuadrature quadrature(pdf, hints);
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

    const ChiSquareResult counted = chi_square_counts(observed, expected, [&](int b) {
        return b == cells ? std::string("outside")
                          : "cell c " + std::to_string(b / n_phi) + " phi " + std::to_string(b % n_phi);
    });
    result.statistic = counted.statistic;
    result.dof = counted.dof;
    result.p_value = counted.p_value;
    result.failure = counted.failure;
    result.worst = counted.worst;
    return result;
}

}  // namespace rtlab::test
