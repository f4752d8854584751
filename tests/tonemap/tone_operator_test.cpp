#include <rtlab/core/error.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
// Two grey pixels of luminance 1 and 100: log-average = sqrt(1.0001 * 100.0001) = 10.000505.
Image two_greys() {
    Image img(2, 1);
    img.at(0, 0) = RGB(1.0f);
    img.at(1, 0) = RGB(100.0f);
    return img;
}

Image apply(const std::string& op, Params params, const Image& img, ToneReport* report = nullptr) {
    static const ToneRegistry registry = make_tone_registry();
    return registry.create(op, std::move(params))->apply(img, report);
}

bool all_in_unit_range(const Image& img) {
    for (const RGB& p : img.pixels())
        for (int k = 0; k < 3; ++k)
            if (!(p[k] >= 0.0f && p[k] <= 1.0f)) return false;
    return true;
}
}  // namespace

TEST_CASE("log-average and maximum luminance", "[tonemap]") {
    const LuminanceStats s = measure_luminance(two_greys());
    CHECK(s.log_average == Approx(10.000505).epsilon(1e-6));
    CHECK(s.max_luminance == Approx(100.0));
    CHECK(s.invalid_pixels == 0);
    // Rec. 709 weights: pure red has luminance 0.2126.
    Image red(1, 1, RGB(1, 0, 0));
    CHECK(measure_luminance(red).max_luminance == Approx(0.2126));
}

TEST_CASE("Reinhard against hand-computed values", "[tonemap]") {
    ToneReport report;
    const Image out = apply("reinhard", Params{}, two_greys(), &report);
    // scale = 0.18 / 10.000505 = 0.0179991; L = 0.0179991 and 1.79991; white = the largest, 1.79991:
    // L_d(1.8) = 1.8 (1 + 1.8 / 3.24) / 2.8 = 1.0;  L_d(0.018) = 0.018 (1 + 0.018 / 3.24) / 1.018 = 0.0177800.
    CHECK(report.scale == Approx(0.0179991).epsilon(1e-5));
    CHECK(out.at(1, 0).g == Approx(1.0f).epsilon(1e-5));
    CHECK(out.at(0, 0).g == Approx(0.0177800f).epsilon(1e-4));
    // The simple form (white = 0 means infinite): L / (1 + L) = 1.8 / 2.8 = 0.642857.
    const Image simple = apply("reinhard", Params{}.set("white", 0.0), two_greys());
    CHECK(simple.at(1, 0).g == Approx(0.642857f).epsilon(1e-4));
    // Key 0.36 doubles the scale: L = 3.6 with white 3.6 still maps the maximum to 1.
    const Image bright = apply("reinhard", Params{}.set("key", 0.36), two_greys());
    CHECK(bright.at(1, 0).g == Approx(1.0f).epsilon(1e-5));
    CHECK(bright.at(0, 0).g > out.at(0, 0).g);
}

TEST_CASE("Ward against hand-computed values", "[tonemap]") {
    ToneReport report;
    const Image out = apply("ward", Params{}, two_greys(), &report);
    // L_dmax = 100, L_da = 50, L_wa = 10.000505: 50^0.4 = 4.781762, 10.000505^0.4 = 2.511937,
    // m = ((1.219 + 4.781762) / (1.219 + 2.511937))^2.5 / 100 = 1.608387^2.5 / 100 = 0.0328074.
    CHECK(report.scale == Approx(0.0328074).epsilon(1e-4));
    CHECK(out.at(0, 0).g == Approx(0.0328074f).epsilon(1e-4));
    CHECK(out.at(1, 0).g == 1.0f);  // 3.28 clamps
    const Image dim = apply("ward", Params{}.set("ldmax", 500.0), two_greys());
    CHECK(dim.at(0, 0).g < out.at(0, 0).g);  // a brighter display needs a smaller fraction of it
}

TEST_CASE("exposure and ACES against hand-computed values", "[tonemap]") {
    Image img(1, 1, RGB(0.25f, 1.0f, 4.0f));
    const Image e = apply("exposure", Params{}.set("stops", 1.0), img);
    CHECK(e.at(0, 0) == RGB(0.5f, 1.0f, 1.0f));
    const Image a = apply("aces", Params{}, img);
    // f(1) = (2.51 + 0.03) / (2.43 + 0.59 + 0.14) = 2.54 / 3.16 = 0.803797.
    CHECK(a.at(0, 0).g == Approx(0.803797f).epsilon(1e-5));
    // f(0.25) = 0.25 (0.6275 + 0.03) / (0.25 (0.6075 + 0.59) + 0.14) = 0.164375 / 0.439375 = 0.374111.
    CHECK(a.at(0, 0).r == Approx(0.374111f).epsilon(1e-5));
}

TEST_CASE("every operator is monotonic in luminance", "[tonemap]") {
    Image ramp(64, 1);
    for (int x = 0; x < 64; ++x) ramp.at(x, 0) = RGB(std::pow(10.0f, -3.0f + 6.0f * static_cast<float>(x) / 63.0f));
    for (const char* op : {"ward", "reinhard", "exposure", "aces"}) {
        const Image out = apply(op, Params{}, ramp);
        for (int x = 1; x < 64; ++x) {
            INFO(op << " at " << x);
            REQUIRE(out.at(x, 0).g >= out.at(x - 1, 0).g);
        }
    }
}

TEST_CASE("stability: black, single pixel, NaN and inf, 12 decades", "[tonemap]") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    Image black(4, 4);
    Image single(1, 1, RGB(3.0f));
    Image broken(3, 1);
    broken.at(0, 0) = RGB(nan, 1.0f, 1.0f);
    broken.at(1, 0) = RGB(inf);
    broken.at(2, 0) = RGB(0.5f, -2.0f, 0.25f);
    Image wide(13, 1);
    for (int x = 0; x < 13; ++x) wide.at(x, 0) = RGB(std::pow(10.0f, static_cast<float>(x - 6)));
    for (const char* op : {"ward", "reinhard", "exposure", "aces"}) {
        INFO(op);
        for (const Image* img : {&black, &single, &broken, &wide}) {
            ToneReport report;
            const Image out = apply(op, Params{}, *img, &report);
            CHECK(all_in_unit_range(out));
            CHECK(std::isfinite(report.log_average));
            CHECK(std::isfinite(report.scale));
        }
        ToneReport report;
        const Image out = apply(op, Params{}, broken, &report);
        CHECK(report.invalid_pixels == 2);
        CHECK(out.at(0, 0) == RGB{});  // not spread: written black
        CHECK(out.at(1, 0) == RGB{});
        CHECK(out.at(2, 0).g == 0.0f);  // negative components count as 0
    }
    // The single pixel maps to white under Reinhard's default white point.
    CHECK(apply("reinhard", Params{}, single).at(0, 0).g == Approx(1.0f).epsilon(1e-5));
}

TEST_CASE("the registry names and checks operators and parameters", "[tonemap]") {
    const ToneRegistry r = make_tone_registry();
    CHECK(r.names() == std::vector<std::string>{"aces", "exposure", "reinhard", "ward"});
    CHECK_THROWS_WITH(r.create("drago", Params{}), Contains("unknown tone operator 'drago'") && Contains("reinhard"));
    CHECK_THROWS_WITH(r.create("reinhard", Params{}.set("kee", 0.2)), Contains("'kee'"));
    CHECK_THROWS_WITH(r.create("reinhard", Params{}.set("key", -1.0)), Contains("key must be positive"));
    CHECK_THROWS_WITH(r.create("ward", Params{}.set("ldmax", std::string("bright"))),
                      Contains("'ldmax' must be a number"));
    CHECK_THROWS_WITH(r.create("exposure", Params{}.set("stops", 1000.0)), Contains("stops must lie in"));
}
