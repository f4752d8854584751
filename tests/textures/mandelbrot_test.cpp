#include <rtlab/textures/mandelbrot.hpp>
#include <rtlab/textures/texture.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace rtlab;

TEST_CASE("mandelbrot points known to be inside the set stay inside", "[mandelbrot]") {
    // c = 0: z stays 0. c = -1: 0, -1, 0, -1, ... (period 2). c = -2: 0, -2, 2, 2, ... (|z| = 2 never
    // exceeds R = 2). c = 0.5i: inside the main cardioid (q (q + x - 1/4) <= y^2 / 4 with q = (x - 1/4)^2 + y^2:
    // 0.3125 * 0.0625 = 0.0195 <= 0.0625). c = i: 0, i, -1 + i, -i, -1 + i, ... (pre-periodic).
    // c = -1.3: in the period-4 bulb.
    for (const auto& [re, im] : {std::pair{0.0, 0.0}, {-1.0, 0.0}, {-2.0, 0.0}, {0.0, 0.5}, {0.0, 1.0}, {-1.3, 0.0}}) {
        INFO("c = " << re << " + " << im << "i");
        CHECK(mandelbrot_escape(re, im, 1000, 2.0).inside);
        CHECK(mandelbrot_escape(re, im, 1000, 256.0).inside);
        CHECK(mandelbrot_escape(re, im, 1000, 2.0).smooth == 1000.0);
    }
}

TEST_CASE("mandelbrot escape counts match the orbit computed by hand", "[mandelbrot]") {
    // c = 1: z = 1, 2, 5: |z_3| > 2 first.
    const auto one = mandelbrot_escape(1.0, 0.0, 100, 2.0);
    CHECK_FALSE(one.inside);
    CHECK(one.iterations == 3);
    // mu = 3 - log2(ln 5 / ln 2) = 3 - log2(2.3219) = 1.7845
    CHECK(one.smooth == Approx(3.0 - std::log2(std::log(5.0) / std::log(2.0))).epsilon(1e-12));
    // c = 0.5: z = 0.5, 0.75, 1.0625, 1.62890625, 3.1533...: n = 5.
    CHECK(mandelbrot_escape(0.5, 0.0, 100, 2.0).iterations == 5);
    // c = 2i: z = 2i, -4 + 2i: n = 2 (|z_1| = 2 is not > 2).
    CHECK(mandelbrot_escape(0.0, 2.0, 100, 2.0).iterations == 2);
    // c = 3: |z_1| = 3 > 2: n = 1.
    CHECK(mandelbrot_escape(3.0, 0.0, 100, 2.0).iterations == 1);
    // The iteration limit is honoured: c = 0.5 with a limit of 4 counts as inside.
    CHECK(mandelbrot_escape(0.5, 0.0, 4, 2.0).inside);
}

TEST_CASE("mandelbrot near the neck escapes after about pi over epsilon iterations", "[mandelbrot]") {
    // c = -0.75 + 0.1i is just outside: not in the period-2 disc (|c + 1| = 0.269 > 0.25) nor the cardioid.
    // Boll (1991): c = -0.75 + eps i escapes after N(eps) with eps N(eps) -> pi. Likewise c = 1/4 + eps
    // escapes after about pi / sqrt(eps).
    const auto neck = mandelbrot_escape(-0.75, 0.1, 10000, 2.0);
    CHECK_FALSE(neck.inside);
    CHECK(neck.iterations * 0.1 == Approx(std::numbers::pi).margin(0.3));
    const auto fine = mandelbrot_escape(-0.75, 0.001, 100000, 2.0);
    CHECK_FALSE(fine.inside);
    CHECK(fine.iterations * 0.001 == Approx(std::numbers::pi).margin(0.01));
    const auto cusp = mandelbrot_escape(0.25 + 1e-4, 0.0, 100000, 2.0);
    CHECK_FALSE(cusp.inside);
    CHECK(cusp.iterations * 0.01 == Approx(std::numbers::pi).margin(0.1));
    // The points just inside the neck and the cusp stay inside.
    CHECK(mandelbrot_escape(-0.75, 0.0, 100000, 2.0).inside);
    CHECK(mandelbrot_escape(0.25, 0.0, 100000, 2.0).inside);
}

TEST_CASE("smooth mandelbrot count has no steps where the integer count jumps", "[mandelbrot]") {
    // Along the real axis from 0.3 to 2, every point escapes and n drops from dozens to 1.
    const int samples = 20000;
    double worst_smooth_jump = 0.0;
    int integer_jumps = 0;
    auto prev = mandelbrot_escape(0.3, 0.0, 1000, 1e4);
    for (int k = 1; k <= samples; ++k) {
        const double c = 0.3 + 1.7 * k / samples;
        const auto e = mandelbrot_escape(c, 0.0, 1000, 1e4);
        REQUIRE_FALSE(e.inside);
        if (e.iterations != prev.iterations) {
            ++integer_jumps;
            worst_smooth_jump = std::max(worst_smooth_jump, std::abs(e.smooth - prev.smooth));
        }
        prev = e;
    }
    CHECK(integer_jumps >= 10);
    CHECK(worst_smooth_jump < 0.02);  // the integer count jumps by 1 at each of these places
    // With the smallest radius the formula is only approximate: the steps are visible.
    double worst_r2 = 0.0;
    prev = mandelbrot_escape(0.3, 0.0, 1000, 2.0);
    for (int k = 1; k <= samples; ++k) {
        const auto e = mandelbrot_escape(0.3 + 1.7 * k / samples, 0.0, 1000, 2.0);
        if (e.iterations != prev.iterations) worst_r2 = std::max(worst_r2, std::abs(e.smooth - prev.smooth));
        prev = e;
    }
    CHECK(worst_r2 > worst_smooth_jump);
}

TEST_CASE("mandelbrot texture maps the uv window and colours inside and outside", "[mandelbrot]") {
    const TextureRegistry r = make_texture_registry();
    Params p;
    p.set("center", Params::List{-0.5, 0.0}).set("zoom", 1.0).set("inside", Params::List{1, 0, 0});
    p.set("outside", 0.0).set("edge", 1.0);
    const auto t = r.create("mandelbrot", p);
    auto at = [&](float u, float v) { return t->eval(TextureLookup{{u, v}, {}, {}}); };
    // uv (0.5, 0.5) is the centre c = -0.5: inside. u = 0.5 + (c_re + 0.5) / 3.
    CHECK(at(0.5f, 0.5f) == RGB(1, 0, 0));
    CHECK(at(0.5f - 0.5f / 3.0f, 0.5f) == RGB(1, 0, 0));  // c = -1
    CHECK(at(1.0f, 0.5f).g < 0.5f);                       // c = 1: escapes fast, near "outside"
    CHECK(at(1.0f, 0.5f).r == at(1.0f, 0.5f).g);
    // zoom 10 around c = 1: the whole window escapes; v moves along the imaginary axis.
    const auto z = r.create("mandelbrot", Params{}.set("center", Params::List{1.0, 0.0}).set("zoom", 10.0));
    for (float u : {0.0f, 0.5f, 1.0f}) CHECK(z->eval(TextureLookup{{u, 0.5f}, {}, {}}) != RGB(0.0f));
    // The smooth colour changes continuously along a line, the stepped one does not.
    const auto smooth = r.create("mandelbrot", Params{}.set("outside", 0.0).set("edge", 1.0));
    const auto stepped = r.create("mandelbrot", Params{}.set("outside", 0.0).set("edge", 1.0).set("smooth", false));
    float worst_smooth = 0.0f, worst_stepped = 0.0f;
    for (int k = 0; k < 2000; ++k) {
        const float u0 = 0.95f + 0.05f * k / 2000.0f, u1 = 0.95f + 0.05f * (k + 1) / 2000.0f;
        worst_smooth = std::max(worst_smooth,
                                std::abs(smooth->eval({{u1, 0.5f}, {}, {}}).r - smooth->eval({{u0, 0.5f}, {}, {}}).r));
        worst_stepped = std::max(
            worst_stepped, std::abs(stepped->eval({{u1, 0.5f}, {}, {}}).r - stepped->eval({{u0, 0.5f}, {}, {}}).r));
    }
    CHECK(worst_smooth < 0.01f);
    CHECK(worst_stepped > 0.02f);
}
