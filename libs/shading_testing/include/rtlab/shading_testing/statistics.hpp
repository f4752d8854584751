#pragma once
/// \brief The distributions a Monte Carlo test compares against, written here: chi-square survival (from the
/// regularised incomplete gamma function), exact binomial tails, and Sidak's multiple-test correction.

namespace rtlab::shading_testing {

/// The regularised incomplete gamma functions P(a, x) = gamma(a, x) / Gamma(a) and Q = 1 - P, for a > 0, x >= 0.
double regularised_gamma_p(double a, double x);
double regularised_gamma_q(double a, double x);

/// The probability that a chi-square variable with `dof` degrees of freedom exceeds `statistic` (the p-value),
/// with full relative precision far in the tail.
double chi_square_survival(double statistic, int dof);

/// Two-sided exact binomial test: twice the smaller tail probability of seeing k successes in n trials of
/// probability p, capped at 1.
double binomial_p_value(int k, int n, double p);

/// The significance level for each of `tests` independent tests so that all of them pass with probability
/// 1 - family_alpha when every null hypothesis holds (Sidak).
double sidak_level(double family_alpha, int tests);

}  // namespace rtlab::shading_testing
