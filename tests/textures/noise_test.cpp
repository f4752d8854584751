#include <rtlab/core/rng.hpp>
#include <rtlab/textures/fractal_noise.hpp>
#include <rtlab/textures/perlin_noise.hpp>
#include <rtlab/textures/simplex_noise.hpp>
#include <rtlab/textures/texture.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace rtlab;

namespace {
const PerlinNoise perlin;
const SimplexNoise simplex;

double uniform(Rng& rng, double lo, double hi) { return lo + (hi - lo) * rng.uniform(); }

// One-sided difference quotients of f at x, from the left and from the right.
template <class F>
std::pair<double, double> one_sided_slopes(F&& f, double x, double h) {
    const double left = (static_cast<double>(f(x)) - f(x - h)) / h;
    const double right = (static_cast<double>(f(x + h)) - f(x)) / h;
    return {left, right};
}
}  // namespace

TEST_CASE("improved Perlin noise is exactly zero at every integer lattice point", "[noise]") {
    for (int i = -6; i <= 6; ++i)
        for (int j = -6; j <= 6; ++j) {
            REQUIRE(perlin.eval(i, j) == 0.0f);
            for (int k = -6; k <= 6; k += 3) REQUIRE(perlin.eval(i, j, k) == 0.0f);
        }
    // Far out, too: the fraction is computed exactly.
    CHECK(perlin.eval(1e5, -1e5, 123456.0) == 0.0f);
    CHECK(perlin.eval(-4e9, 7e12) == 0.0f);
    CHECK(perlin.eval(1e300, 1e300, -1e300) == 0.0f);
    // Between lattice points it is not zero everywhere.
    CHECK(std::abs(perlin.eval(0.5, 0.5, 0.5)) + std::abs(perlin.eval(1.3, 2.7, 0.4)) > 0.0f);
}

TEST_CASE("simplex noise is zero at the vertices of its simplex lattice", "[noise]") {
    // Vertex (i, j) of the skewed lattice unskews to (i, j) - (i + j) G2; (i, j, k) to (i, j, k) - (i + j + k) / 6.
    const double g2 = (3.0 - std::sqrt(3.0)) / 6.0;
    for (int i = -5; i <= 5; ++i)
        for (int j = -5; j <= 5; ++j) {
            const double t = (i + j) * g2;
            REQUIRE(std::abs(simplex.eval(i - t, j - t)) < 1e-6f);
            for (int k = -5; k <= 5; k += 5) {
                const double t3 = (i + j + k) / 6.0;
                REQUIRE(std::abs(simplex.eval(i - t3, j - t3, k - t3)) < 1e-6f);
            }
        }
}

TEST_CASE("noise values stay within their stated ranges and use most of them", "[noise]") {
    Rng rng(7);
    float lo[4] = {0, 0, 0, 0}, hi[4] = {0, 0, 0, 0};
    const FractalParams f{6, 2.0, 0.5f};
    float fbm_lo = 0, fbm_hi = 0, turb_lo = 1, turb_hi = 0;
    for (int n = 0; n < 100000; ++n) {
        const double x = uniform(rng, -300, 300), y = uniform(rng, -300, 300), z = uniform(rng, -300, 300);
        const float v[4] = {perlin.eval(x, y), perlin.eval(x, y, z), simplex.eval(x, y), simplex.eval(x, y, z)};
        for (int k = 0; k < 4; ++k) {
            lo[k] = std::min(lo[k], v[k]);
            hi[k] = std::max(hi[k], v[k]);
        }
        if (n % 4 == 0) {
            const float b = fbm(perlin, x, y, z, f), t = turbulence(simplex, x, y, z, f);
            fbm_lo = std::min(fbm_lo, b), fbm_hi = std::max(fbm_hi, b);
            turb_lo = std::min(turb_lo, t), turb_hi = std::max(turb_hi, t);
        }
    }
    for (int k = 0; k < 4; ++k) {
        INFO("noise " << k << " range [" << lo[k] << ", " << hi[k] << "]");
        CHECK(lo[k] >= -1.0f);
        CHECK(hi[k] <= 1.0f);
        CHECK(lo[k] < -0.6f);
        CHECK(hi[k] > 0.6f);
    }
    CHECK(fbm_lo >= -1.0f);
    CHECK(fbm_hi <= 1.0f);
    CHECK(fbm_hi - fbm_lo > 0.5f);
    CHECK(turb_lo >= 0.0f);
    CHECK(turb_hi <= 1.0f);
    CHECK(turb_hi > 0.2f);
}

TEST_CASE("Perlin noise value and gradient are continuous across lattice cell borders", "[noise]") {
    // At a border x = k the two cells use different corner sets; with the quintic fade both one-sided
    // slopes must agree (to O(h)), in every axis, in 2D and 3D.
    Rng rng(11);
    const double h = 1e-3;
    double worst_slope_gap = 0.0, worst_value_gap = 0.0, largest_slope = 0.0;
    for (int n = 0; n < 300; ++n) {
        const double k = std::floor(uniform(rng, -50, 50));
        const double a = uniform(rng, -50, 50), b = uniform(rng, -50, 50);
        const auto fx = [&](double x) { return perlin.eval(x, a, b); };
        const auto fy = [&](double y) { return perlin.eval(a, y, b); };
        const auto fz = [&](double z) { return perlin.eval(a, b, z); };
        const auto f2x = [&](double x) { return perlin.eval(x, a); };
        const auto f2y = [&](double y) { return perlin.eval(a, y); };
        auto check = [&](auto&& f) {
            const auto [left, right] = one_sided_slopes(f, k, h);
            worst_slope_gap = std::max(worst_slope_gap, std::abs(left - right));
            largest_slope = std::max(largest_slope, std::abs(left));
            const double eps = 1e-7;
            worst_value_gap = std::max(worst_value_gap, std::abs(static_cast<double>(f(k + eps)) - f(k - eps)));
        };
        check(fx), check(fy), check(fz), check(f2x), check(f2y);
    }
    CHECK(largest_slope > 0.5);     // the slopes compared are not all zero
    CHECK(worst_slope_gap < 0.02);  // one-sided slopes agree: no kink at cell borders
    CHECK(worst_value_gap < 1e-5);  // and no jump
}

TEST_CASE("simplex noise has no jumps at simplex or cell borders", "[noise]") {
    // Lipschitz check across the borders of the skewed cells and the diagonals that split them, where a
    // kernel radius that is too large (r^2 = 0.6 in 3D) leaves small jumps.
    Rng rng(13);
    const double g2 = (3.0 - std::sqrt(3.0)) / 6.0;
    double worst_ratio = 0.0;
    const double d = 1e-5;
    for (int n = 0; n < 2000; ++n) {
        // A point on a skewed cell border (skewed x = integer), unskewed.
        const double i = std::floor(uniform(rng, -40, 40)), sy = uniform(rng, -40, 40);
        const double t = (i + sy) * g2;
        const double x = i - t, y = sy - t;
        worst_ratio = std::max(worst_ratio, std::abs(simplex.eval(x + d, y) - simplex.eval(x - d, y)) / (2 * d));
        // A point on the diagonal x0 = y0 inside a cell.
        const double c = uniform(rng, 0, 1), j = std::floor(uniform(rng, -40, 40));
        const double td = (i + c + j + c) * g2;
        const double xd = i + c - td, yd = j + c - td;
        worst_ratio = std::max(worst_ratio, std::abs(simplex.eval(xd + d, yd) - simplex.eval(xd - d, yd)) / (2 * d));
        // 3D: a point whose skewed x, x + (x + y + z) / 3, is the integer m; steps along every axis.
        const double py = uniform(rng, -40, 40), pz = uniform(rng, -40, 40), m = std::floor(uniform(rng, -40, 40));
        const double bx = (3.0 * m - py - pz) / 4.0;
        for (int axis = 0; axis < 3; ++axis) {
            double q[3] = {bx, py, pz};
            double r[3] = {bx, py, pz};
            q[axis] += d, r[axis] -= d;
            worst_ratio = std::max(worst_ratio,
                                   std::abs(simplex.eval(q[0], q[1], q[2]) - simplex.eval(r[0], r[1], r[2])) / (2 * d));
        }
    }
    // The steepest slope of the scaled noise is a few units; a jump of 1e-3 would read as 50 here.
    CHECK(worst_ratio < 10.0);
}

TEST_CASE("noise far from the origin is finite and periodic and resolves small steps", "[noise]") {
    // The permutation has period 256 in every axis and 1e5 = 390 * 256 + 160, so noise at 1e5 + f equals
    // noise at 160 + f when the fraction is kept exactly.
    Rng rng(17);
    for (int n = 0; n < 200; ++n) {
        const double f = uniform(rng, 0, 1), g = uniform(rng, 0, 1), e = uniform(rng, 0, 1);
        REQUIRE(perlin.eval(1e5 + f, 1e5 + g, -1e5 + e) ==
                Approx(perlin.eval(160 + f, 160 + g, -160 + e)).margin(1e-6));
        REQUIRE(perlin.eval(1e5 + f, -1e5 + g) == Approx(perlin.eval(160 + f, -160 + g)).margin(1e-6));
    }
    // Steps of 1e-3 at 1e5 all give different values (float coordinates would plateau over 7.8e-3), and
    // the values vary.
    int equal_neighbours = 0;
    float lo = 1, hi = -1;
    float prev = perlin.eval(1e5 + 0.3, 1e5 + 0.3, 1e5 + 0.3);
    for (int k = 1; k < 1000; ++k) {
        const float v = perlin.eval(1e5 + 0.3 + k * 1e-3, 1e5 + 0.3, 1e5 + 0.3);
        REQUIRE(std::isfinite(v));
        equal_neighbours += v == prev ? 1 : 0;
        lo = std::min(lo, v), hi = std::max(hi, v);
        prev = v;
    }
    CHECK(equal_neighbours < 10);
    CHECK(hi - lo > 0.1f);
    // fBm with lacunarity 2 keeps the period (each octave frequency is an integer), and simplex stays finite.
    const FractalParams fr{8, 2.0, 0.5f};
    CHECK(fbm(perlin, 1e5 + 0.37, 1e5 + 0.11, 1e5 + 0.73, fr) ==
          Approx(fbm(perlin, 160.37, 160.11, 160.73, fr)).margin(1e-5));
    float slo = 1, shi = -1;
    for (int k = 0; k < 100; ++k) {
        const float v = simplex.eval(1e5 + 0.1 * k, -1e5 + 0.05 * k, 1e5);
        REQUIRE(std::isfinite(v));
        slo = std::min(slo, v), shi = std::max(shi, v);
    }
    CHECK(shi - slo > 0.1f);
    // Non-finite input gives 0 instead of NaN or a crash.
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(perlin.eval(inf, 0.0, 0.0) == 0.0f);
    CHECK(perlin.eval(nan, 1.5) == 0.0f);
    CHECK(simplex.eval(0.3, nan, 0.1) == 0.0f);
    CHECK(simplex.eval(-inf, 0.2) == 0.0f);
}

TEST_CASE("noise seeds give different fields and the same seed gives the same field", "[noise]") {
    const PerlinNoise a(0), b(0), c(12345);
    int differ = 0;
    for (int k = 0; k < 50; ++k) {
        const double x = 0.37 + k * 1.13, y = 0.21 + k * 0.71, z = 0.5;
        REQUIRE(a.eval(x, y, z) == b.eval(x, y, z));
        differ += a.eval(x, y, z) != c.eval(x, y, z) ? 1 : 0;
    }
    CHECK(differ > 40);
}

TEST_CASE("noise textures map patterns to colours in 2D and 3D", "[noise]") {
    const TextureRegistry r = make_texture_registry();
    Rng rng(19);
    for (const char* name : {"perlin", "simplex"}) {
        for (const char* pattern : {"noise", "fbm", "turbulence", "marble"}) {
            for (double dim : {2.0, 3.0}) {
                Params p;
                p.set("pattern", std::string(pattern)).set("dimension", dim).set("scale", 3.0);
                p.set("color1", Params::List{1, 0, 0}).set("color2", Params::List{0, 0, 1});
                const auto t = r.create(name, p);
                float blo = 1, bhi = 0;
                for (int n = 0; n < 400; ++n) {
                    TextureLookup q;
                    q.uv = {static_cast<float>(uniform(rng, -5, 5)), static_cast<float>(uniform(rng, -5, 5))};
                    q.point = {static_cast<float>(uniform(rng, -5, 5)), static_cast<float>(uniform(rng, -5, 5)),
                               static_cast<float>(uniform(rng, -5, 5))};
                    const RGB c = t->eval(q);
                    // A blend of the two colours: r + b = 1, g = 0.
                    REQUIRE(c.r + c.b == Approx(1.0f).margin(1e-5));
                    REQUIRE(c.g == 0.0f);
                    REQUIRE(c.b >= 0.0f);
                    REQUIRE(c.b <= 1.0f);
                    blo = std::min(blo, c.b), bhi = std::max(bhi, c.b);
                }
                INFO(name << " " << pattern << " " << dim << "D spans [" << blo << ", " << bhi << "]");
                CHECK(bhi - blo > 0.2f);
            }
        }
    }
    // dimension 2 reads uv only, dimension 3 the point only.
    const auto t2 = r.create("perlin", Params{}.set("dimension", 2.0));
    const auto t3 = r.create("perlin", Params{}.set("dimension", 3.0));
    const TextureLookup q1{{0.3f, 0.6f}, {1.1f, 2.2f, 3.3f}, {}}, q2{{0.3f, 0.6f}, {5.1f, 0.2f, 7.3f}, {}},
        q3{{0.7f, 0.2f}, {1.1f, 2.2f, 3.3f}, {}};
    CHECK(t2->eval(q1) == t2->eval(q2));
    CHECK(t2->eval(q1) != t2->eval(q3));
    CHECK(t3->eval(q1) == t3->eval(q3));
    CHECK(t3->eval(q1) != t3->eval(q2));
    // A non-finite point gives color1 (t = 0) for every pattern, not NaN.
    for (const char* pattern : {"noise", "fbm", "turbulence", "marble"}) {
        const auto t = r.create("perlin", Params{}.set("pattern", std::string(pattern)).set("color1", 0.25));
        CHECK(t->eval(TextureLookup{{}, {std::nanf(""), 1.0f, 2.0f}, {}}) == RGB(0.25f));
    }
    // Plain noise: t = 0.5 + 0.5 n, so at an integer point (n = 0) the colour is the mid blend.
    const auto mid = r.create("perlin", Params{}.set("dimension", 3.0));
    CHECK(mid->eval(TextureLookup{{}, {2.0f, -3.0f, 5.0f}, {}}) == RGB(0.5f));
}

TEST_CASE("noise colours may be nested textures that see the same lookup", "[noise]") {
    const TextureRegistry r = make_texture_registry();
    // color1: a uv checker of 1 (even) and 0 (odd) tiles, 2 per unit; color2: constant 0.5 in blue only.
    const auto checker = r.create("checker", Params{}.set("tiles_u", 2.0));
    Params p;
    p.set("dimension", 3.0).set("color2", Params::List{0.0, 0.0, 0.5});
    p.set_object<Texture>("color1", checker);
    const auto t = r.create("perlin", p);
    // At an integer point n = 0, so t = 0.5: half the checker plus half of color2.
    CHECK(t->eval(TextureLookup{{0.1f, 0.1f}, {2.0f, -3.0f, 5.0f}, {}}) == RGB(0.5f, 0.5f, 0.75f));  // even tile
    CHECK(t->eval(TextureLookup{{0.6f, 0.1f}, {2.0f, -3.0f, 5.0f}, {}}) == RGB(0.0f, 0.0f, 0.25f));  // odd tile
    // A non-finite point gives color1 unblended: the checker itself.
    CHECK(t->eval(TextureLookup{{0.6f, 0.1f}, {std::nanf(""), 0.0f, 0.0f}, {}}) == RGB(0.0f));
    CHECK(t->eval(TextureLookup{{0.1f, 0.1f}, {std::nanf(""), 0.0f, 0.0f}, {}}) == RGB(1.0f));
}
