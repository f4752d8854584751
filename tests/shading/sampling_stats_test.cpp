// The statistics the sampled-material tests rely on (rtlab::shading_testing), against tabulated values.
#include <rtlab/shading_testing/sphere_quadrature.hpp>
#include <rtlab/shading_testing/statistics.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace rtlab;
using namespace rtlab::shading_testing;

TEST_CASE("the chi-square survival function matches tabulated quantiles", "[shading][statistics]") {
    // Upper 5% and 1% points of the chi-square distribution (any statistics table).
    CHECK(chi_square_survival(3.841459, 1) == Approx(0.05).epsilon(1e-5));
    CHECK(chi_square_survival(18.307038, 10) == Approx(0.05).epsilon(1e-5));
    CHECK(chi_square_survival(23.209251, 10) == Approx(0.01).epsilon(1e-5));
    CHECK(chi_square_survival(124.342113, 100) == Approx(0.05).epsilon(1e-5));
    CHECK(chi_square_survival(3.940299, 10) == Approx(0.95).epsilon(1e-5));  // the series branch
    CHECK(regularised_gamma_p(3.0, 2.0) + regularised_gamma_q(3.0, 2.0) == Approx(1.0).epsilon(1e-14));
    // 2 degrees of freedom: exp(-x / 2) exactly.
    for (double x : {0.1, 1.0, 5.0, 40.0}) CHECK(chi_square_survival(x, 2) == Approx(std::exp(-0.5 * x)).epsilon(1e-9));
}

TEST_CASE("the binomial test gives exact tail probabilities", "[shading][statistics]") {
    // n = 10, p = 0.5: P(X <= 2) = 56 / 1024, two-sided 112 / 1024.
    CHECK(binomial_p_value(2, 10, 0.5) == Approx(112.0 / 1024.0).epsilon(1e-12));
    CHECK(binomial_p_value(5, 10, 0.5) == 1.0);
    CHECK(binomial_p_value(10, 10, 1.0) == 1.0);
    CHECK(binomial_p_value(9, 10, 1.0) == 0.0);
}

TEST_CASE("sidak's level keeps the family's significance", "[shading][statistics]") {
    const double a = sidak_level(0.01, 100);
    CHECK(std::pow(1.0 - a, 100) == Approx(0.99).epsilon(1e-12));
}

TEST_CASE("the sphere quadrature finds a lobe narrower than its first nodes", "[shading][statistics]") {
    // A lobe 1 / (pi s^2 (1 + theta^2 / s^2)^2) of width s = 1e-3 rad about a tilted axis (normalised to 1e-6:
    // its tail beyond the sphere is that small), resolved through the hint (it is nowhere 0, so no node
    // sees an edge).
    const Vec3 axis = direction_at(0.3, 2.0);
    const double s2 = 1e-6;
    const auto lobe = [&](const Vec3& w) {
        const Vec3 d = w - axis;  // chord: theta^2 = |d|^2 to fourth order
        const double t2 = double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
        return 1.0 / (std::numbers::pi * s2 * (1.0 + t2 / s2) * (1.0 + t2 / s2));
    };
    CHECK(SphereQuadrature(lobe, {axis}).integrate_sphere() == Approx(1.0).epsilon(1e-4));
    // A smooth density: cos theta / pi over the upper hemisphere.
    const auto cosine = [](const Vec3& w) { return w.z > 0.0f ? w.z / std::numbers::pi : 0.0; };
    CHECK(SphereQuadrature(cosine, {}).integrate_sphere() == Approx(1.0).epsilon(1e-6));
}

TEST_CASE("the sphere quadrature integrates a lobe's kinked or hard rim along constant cos theta",
          "[shading][statistics]") {
    // The rims the rules on a piece and on its halves misjudge alike: a circle of constant cos theta (a lobe
    // centred on the normal) falls at the same place in every piece along it. Halving every piece and trusting
    // the estimates, a hard rim at cos 0.97 lost 1.7e-3 of its cell's integral, and a cone falling linearly to
    // its rim erred by 3.5e-4 of the sphere's.
    const double w = 0.03;  // 1 - cos of the rim
    const auto cone = [&](const Vec3& v) { return v.z > 1.0 - w ? 1.0 / (2.0 * std::numbers::pi * w) : 0.0; };
    CHECK(SphereQuadrature(cone, {}).integrate(1.0 - 2.0 / 24, 1.0, 0.0, 2.0 * std::numbers::pi / 24) ==
          Approx(1.0 / 24).epsilon(1e-5));
    // x / (pi w), x = 1 - (1 - cos) / w falling to 0 at the rim, on a cosine: each integrates to 1.
    const auto tent = [&](const Vec3& v) {
        const double x = 1.0 - (1.0 - v.z) / w;
        return (v.z > 0.0f ? v.z / std::numbers::pi : 0.0) + (x > 0.0 ? x / (std::numbers::pi * w) : 0.0);
    };
    CHECK(SphereQuadrature(tent, {Vec3(0, 0, 1)}).integrate_sphere(24, 24) == Approx(2.0).epsilon(2e-6));
}
