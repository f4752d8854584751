// Piecewise-constant distributions: sampling is the exact inverse of the cumulative table, the density
// integrates to 1, and cells of weight 0 (whole rows and columns among them) are never drawn, even for the
// numbers at the very edges of [0, 1).
#include <rtlab/core/distribution.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace rtlab;

namespace {

// Weights with runs of zeros (at both ends and inside), a few huge ones and many ordinary ones.
std::vector<float> awkward_weights(std::size_t n, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<float> w(n);
    for (std::size_t i = 0; i < n; ++i) {
        const float r = rng.uniform();
        w[i] = r < 0.3f ? 0.0f : r < 0.33f ? 1e4f * rng.uniform() : rng.uniform();
    }
    w.front() = w.back() = 0.0f;
    return w;
}

// The numbers a sampler may be given that are most likely to find an off-by-one: the table's own entries,
// their float neighbours, 0, the largest float below 1, and random ones.
std::vector<float> probing_numbers(const Distribution1D& d, std::uint64_t seed, int random = 20000) {
    std::vector<float> us{0.0f, 0x1.fffffep-1f};
    for (std::size_t i = 0; i <= d.size(); ++i) {
        const float c = d.cdf(i);
        for (float u : {c, next_float_down(c), next_float_up(c)})
            if (u >= 0.0f && u < 1.0f) us.push_back(u);
    }
    Rng rng(seed);
    for (int k = 0; k < random; ++k) us.push_back(rng.uniform());
    return us;
}

}  // namespace

TEST_CASE("1D sampling inverts the cumulative table exactly and never draws a zero cell", "[distribution]") {
    for (std::size_t n : {1u, 2u, 7u, 1000u, 4096u}) {
        std::vector<float> w = awkward_weights(n, n);
        if (n <= 2) w[n - 1] = 2.0f;  // awkward_weights zeroes both ends
        const Distribution1D d(w);
        INFO("n = " << n);
        for (float u : probing_numbers(d, 3 * n)) {
            const Distribution1D::Sample s = d.sample(u);
            REQUIRE(s.x >= 0.0f);
            REQUIRE(s.x < 1.0f);
            REQUIRE(s.index == d.cell(s.x));
            REQUIRE(w[s.index] > 0.0f);
            REQUIRE(s.pdf == d.pdf(s.x));
            REQUIRE(s.pdf > 0.0f);
            // The cumulative distribution at x, linear within the cell, gives u back.
            const double lo = d.cdf(s.index), hi = d.cdf(s.index + 1);
            const double cdf_x = lo + (double(s.x) * double(n) - double(s.index)) * (hi - lo);
            REQUIRE(cdf_x == Approx(double(u)).margin(4e-7));
        }
        // At the start of a cell of weight > 0 the draw is the cell's left edge (when its step is wide enough for
        // a float to tell: one of under 2^-24 of the total is lost in the table's rounding).
        for (std::size_t i = 0; i < n; ++i) {
            if (!(w[i] > 0.0f) || !(d.cdf(i + 1) > d.cdf(i)) || d.cdf(i) >= 1.0f) continue;
            const Distribution1D::Sample s = d.sample(d.cdf(i));
            REQUIRE(s.index == i);
            REQUIRE(s.x == Approx(double(i) / double(n)).margin(1e-6));
        }
    }
}

TEST_CASE("1D stratified draws fill each cell in proportion to its weight", "[distribution]") {
    // Numbers (k + 1/2) / m, k < m, land in cell i exactly m p_i times, up to one at either end of the cell.
    const std::vector<float> w = awkward_weights(300, 5);
    const Distribution1D d(w);
    double sum = 0.0;
    for (float x : w) sum += x;
    const int m = 1 << 20;
    std::vector<int> count(w.size(), 0);
    for (int k = 0; k < m; ++k) ++count[d.sample((float(k) + 0.5f) / float(m)).index];
    for (std::size_t i = 0; i < w.size(); ++i) {
        const double expected = m * w[i] / sum;
        INFO("cell " << i << " weight " << w[i]);
        CHECK(std::abs(count[i] - expected) <= 2.0);
    }
}

TEST_CASE("1D and 2D densities integrate to 1", "[distribution]") {
    const std::vector<float> w = awkward_weights(777, 9);
    const Distribution1D d(w);
    double integral = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i) integral += d.pdf_of(i) / double(d.size());
    CHECK(integral == Approx(1.0).epsilon(1e-6));
    CHECK(d.integral() == Approx([&] {
              double s = 0.0;
              for (float x : w) s += x;
              return s / double(w.size());
          }()));

    const std::size_t nu = 64, nv = 48;
    const Distribution2D d2(awkward_weights(nu * nv, 10), nu, nv);
    double integral2 = 0.0;
    for (std::size_t r = 0; r < nv; ++r)
        for (std::size_t c = 0; c < nu; ++c)
            integral2 += d2.pdf(Vec2((float(c) + 0.5f) / float(nu), (float(r) + 0.5f) / float(nv)));
    CHECK(integral2 / double(nu * nv) == Approx(1.0).epsilon(1e-5));
}

TEST_CASE("2D sampling never draws a zero row or column and its pdf is pdf()", "[distribution]") {
    const std::size_t nu = 40, nv = 30;
    std::vector<float> w = awkward_weights(nu * nv, 21);
    for (std::size_t c = 0; c < nu; ++c) w[7 * nu + c] = w[29 * nu + c] = w[c] = 0.0f;  // zero rows
    for (std::size_t r = 0; r < nv; ++r) w[r * nu + 3] = w[r * nu + 39] = 0.0f;         // zero columns
    const Distribution2D d(w, nu, nv);
    std::vector<float> probes;
    for (float u : probing_numbers(d.marginal(), 4, 500)) probes.push_back(u);
    Rng rng(8);
    for (std::size_t k = 0; k < probes.size(); ++k) {
        // Pair every probe for the row with the probes of the row it picks, and with random numbers.
        const std::size_t row = d.marginal().sample(probes[k]).index;
        for (float column : probing_numbers(d.conditional(row), k, 20)) {
            for (float ux : {column, rng.uniform()}) {
                const Distribution2D::Sample s = d.sample(Vec2(ux, probes[k]));
                REQUIRE(s.row == row);
                REQUIRE(w[s.row * nu + s.column] > 0.0f);
                REQUIRE(s.uv.x < 1.0f);
                REQUIRE(s.uv.y < 1.0f);
                REQUIRE(s.pdf > 0.0f);
                REQUIRE(s.pdf == Approx(d.pdf(s.uv)).epsilon(1e-6));
                REQUIRE(s.pdf == Approx(double(w[s.row * nu + s.column]) / d.integral()).epsilon(1e-4));
            }
        }
    }
    // A zero cell has density 0 where it is asked about.
    CHECK(d.pdf(Vec2(3.5f / nu, 0.5f)) == 0.0f);
    CHECK(d.pdf(Vec2(0.5f, 7.5f / nv)) == 0.0f);
}

TEST_CASE("an all-zero table is uniform and bad tables are errors", "[distribution]") {
    const std::vector<float> zeros(10, 0.0f);
    const Distribution1D d(zeros);
    CHECK(d.integral() == 0.0);
    CHECK(d.sample(0.55f).x == Approx(0.55f));
    CHECK(d.pdf(0.3f) == 1.0f);
    CHECK_THROWS_AS(Distribution1D(std::vector<float>{}), Error);
    CHECK_THROWS_AS(Distribution1D(std::vector<float>{1.0f, -1.0f}), Error);
    CHECK_THROWS_AS(Distribution1D(std::vector<float>{1.0f, std::nanf("")}), Error);
    CHECK_THROWS_AS(Distribution1D(std::vector<float>{1.0f, INFINITY}), Error);
    CHECK_THROWS_AS(Distribution2D(std::vector<float>(6, 1.0f), 4, 2), Error);
    CHECK_THROWS_AS(Distribution2D(std::vector<float>{}, 0, 0), Error);
}
