#include <rtlab/core/error.hpp>
#include <rtlab/core/param_checks.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// One parameter `name` = value, with a context as the registry would set it.
Params one(const std::string& name, Params::Value value) {
    Params p;
    p.set(name, std::move(value));
    p.set_context("material 'glass'");
    return p;
}

Params none() {
    Params p;
    p.set_context("material 'glass'");
    return p;
}

// Every failure names the object and the parameter.
auto names(const std::string& name, const std::string& problem) {
    return Contains("material 'glass': parameter '" + name + "' " + problem);
}
}  // namespace

TEST_CASE("fail_param names the context and the parameter", "[param_checks]") {
    CHECK_THROWS_AS(fail_param(none(), "ior", "is wrong"), Error);
    CHECK_THROWS_WITH(fail_param(none(), "ior", "is wrong"), "material 'glass': parameter 'ior' is wrong");
}

TEST_CASE("positive_float rejects zero negative NaN and infinity", "[param_checks]") {
    CHECK(positive_float(one("ior", 1.5), "ior", 1.0f) == 1.5f);
    CHECK(positive_float(none(), "ior", 1.25f) == 1.25f);
    CHECK(positive_float(one("ior", 1e-30), "ior", 1.0f) == 1e-30f);  // tiny but > 0
    CHECK(positive_float(one("ior", 0.0), "ior", 1.0f, true) == 0.0f);
    CHECK_THROWS_WITH(positive_float(one("ior", 0.0), "ior", 1.0f), names("ior", "must be finite and > 0, got 0"));
    CHECK_THROWS_WITH(positive_float(one("ior", -0.0), "ior", 1.0f), names("ior", "must be finite and > 0"));
    CHECK_THROWS_WITH(positive_float(one("ior", -2.0), "ior", 1.0f, true),
                      names("ior", "must be finite and >= 0, got -2"));
    CHECK_THROWS_WITH(positive_float(one("ior", kNaN), "ior", 1.0f), names("ior", "must be finite"));
    CHECK_THROWS_WITH(positive_float(one("ior", kInf), "ior", 1.0f), names("ior", "must be finite"));
    CHECK_THROWS_WITH(positive_float(one("ior", 1e300), "ior", 1.0f),
                      names("ior", "must be finite"));  // float overflow
    CHECK_THROWS_WITH(positive_float(one("ior", std::string("high")), "ior", 1.0f),
                      names("ior", "must be a number, not a string"));
}

TEST_CASE("float_in_range accepts both ends and rejects what lies outside", "[param_checks]") {
    CHECK(float_in_range(one("roughness", 0.0), "roughness", 0.5f, 0.0f, 1.0f) == 0.0f);
    CHECK(float_in_range(one("roughness", 1.0), "roughness", 0.5f, 0.0f, 1.0f) == 1.0f);
    CHECK(float_in_range(one("roughness", 0.3), "roughness", 0.5f, 0.0f, 1.0f) == 0.3f);
    CHECK(float_in_range(none(), "roughness", 0.5f, 0.0f, 1.0f) == 0.5f);
    CHECK(float_in_range(one("roughness", -0.0), "roughness", 0.5f, 0.0f, 1.0f) == 0.0f);  // -0 == 0
    CHECK_THROWS_WITH(float_in_range(one("roughness", 1.0000001), "roughness", 0.5f, 0.0f, 1.0f),
                      names("roughness", "must be finite and in [0, 1], got 1.0000001"));
    CHECK_THROWS_WITH(float_in_range(one("roughness", -1e-20), "roughness", 0.5f, 0.0f, 1.0f),
                      names("roughness", "must be finite and in [0, 1], got -1e-20"));
    CHECK_THROWS_WITH(float_in_range(one("roughness", kNaN), "roughness", 0.5f, 0.0f, 1.0f),
                      names("roughness", "must be finite and in [0, 1], got nan"));
    // An infinite range end does not let an infinite value through.
    const float big = std::numeric_limits<float>::infinity();
    CHECK(float_in_range(one("scale", 1e30), "scale", 1.0f, 0.0f, big) == 1e30f);
    CHECK_THROWS_WITH(float_in_range(one("scale", kInf), "scale", 1.0f, 0.0f, big), names("scale", "must be finite"));
    CHECK_THROWS_WITH(float_in_range(one("scale", -kInf), "scale", 1.0f, -big, big), names("scale", "must be finite"));
    CHECK_THROWS_WITH(float_in_range(one("roughness", Params::List{0.1, 0.2}), "roughness", 0.5f, 0.0f, 1.0f),
                      names("roughness", "must be a number, not a list of numbers"));
}

TEST_CASE("bounded_int accepts its bounds and rejects fractions and values beyond", "[param_checks]") {
    CHECK(bounded_int(one("depth", 1.0), "depth", 5, 1, 16) == 1);
    CHECK(bounded_int(one("depth", 16.0), "depth", 5, 1, 16) == 16);
    CHECK(bounded_int(none(), "depth", 5, 1, 16) == 5);
    CHECK_THROWS_WITH(bounded_int(one("depth", 0.0), "depth", 5, 1, 16), names("depth", "must be in [1, 16], got 0"));
    CHECK_THROWS_WITH(bounded_int(one("depth", 17.0), "depth", 5, 1, 16), names("depth", "must be in [1, 16], got 17"));
    CHECK_THROWS_WITH(bounded_int(one("depth", 2.5), "depth", 5, 1, 16), names("depth", "must be an integer"));
    CHECK_THROWS_WITH(bounded_int(one("depth", kNaN), "depth", 5, 1, 16), names("depth", "must be an integer"));
    CHECK_THROWS_WITH(bounded_int(one("depth", kInf), "depth", 5, 1, 16), names("depth", "must be an integer"));
    CHECK_THROWS_WITH(bounded_int(one("depth", 1e10), "depth", 5, 1, 16), names("depth", "must be an integer"));
    CHECK_THROWS_WITH(bounded_int(one("depth", true), "depth", 5, 1, 16),
                      names("depth", "must be an integer, not a boolean"));
}

TEST_CASE("get_vec2 takes one number or two and nothing else", "[param_checks]") {
    CHECK(get_vec2(one("scale", 2.0), "scale", Vec2(1.0f)) == Vec2(2.0f, 2.0f));
    CHECK(get_vec2(one("scale", Params::List{2.0, -3.0}), "scale", Vec2(1.0f)) == Vec2(2.0f, -3.0f));
    CHECK(get_vec2(one("scale", Params::List{4.0}), "scale", Vec2(1.0f)) == Vec2(4.0f, 4.0f));
    CHECK(get_vec2(none(), "scale", Vec2(1.0f, 5.0f)) == Vec2(1.0f, 5.0f));
    CHECK_THROWS_WITH(get_vec2(one("scale", Params::List{1, 2, 3}), "scale", Vec2(1.0f)),
                      names("scale", "must be one number or a list of 2 numbers"));
    CHECK_THROWS_WITH(get_vec2(one("scale", Params::List{}), "scale", Vec2(1.0f)),
                      names("scale", "must be one number or a list of 2 numbers"));
    CHECK_THROWS_WITH(get_vec2(one("scale", Params::List{1.0, kNaN}), "scale", Vec2(1.0f)),
                      names("scale", "must be finite"));
    CHECK_THROWS_WITH(get_vec2(one("scale", -kInf), "scale", Vec2(1.0f)), names("scale", "must be finite"));
    CHECK_THROWS_WITH(get_vec2(one("scale", Params::List{1.0, 1e39}), "scale", Vec2(1.0f)),
                      names("scale", "must be finite"));  // beyond float
    CHECK_THROWS_WITH(get_vec2(one("scale", std::string("big")), "scale", Vec2(1.0f)),
                      names("scale", "must be a list of numbers, not a string"));
}

TEST_CASE("one_of accepts only the listed words and lists them on failure", "[param_checks]") {
    CHECK(one_of(one("mode", std::string("b")), "mode", "a", {"a", "b", "c"}) == "b");
    CHECK(one_of(none(), "mode", "c", {"a", "b", "c"}) == "c");
    CHECK_THROWS_WITH(one_of(one("mode", std::string("B")), "mode", "a", {"a", "b", "c"}),
                      names("mode", "must be one of a, b, c, got 'B'"));  // case matters
    CHECK_THROWS_WITH(one_of(one("mode", std::string("")), "mode", "a", {"a", "b"}),
                      names("mode", "must be one of a, b, got ''"));
    CHECK_THROWS_WITH(one_of(one("mode", 1.0), "mode", "a", {"a", "b"}),
                      names("mode", "must be a string, not a number"));
}

TEST_CASE("finite_rgb takes a grey number or three numbers all finite", "[param_checks]") {
    CHECK(finite_rgb(one("albedo", 0.25), "albedo", RGB(1.0f)) == RGB(0.25f));
    CHECK(finite_rgb(one("albedo", Params::List{0.1, 0.2, 3.0}), "albedo", RGB(1.0f)) == RGB(0.1f, 0.2f, 3.0f));
    CHECK(finite_rgb(none(), "albedo", RGB(0.5f, 0.6f, 0.7f)) == RGB(0.5f, 0.6f, 0.7f));
    CHECK(finite_rgb(one("albedo", -1.0), "albedo", RGB(1.0f)) == RGB(-1.0f));  // finite is all it asks
    CHECK_THROWS_WITH(finite_rgb(one("albedo", Params::List{0.1, kNaN, 0.3}), "albedo", RGB(1.0f)),
                      names("albedo", "must be finite"));
    CHECK_THROWS_WITH(finite_rgb(one("albedo", kInf), "albedo", RGB(1.0f)), names("albedo", "must be finite"));
    CHECK_THROWS_WITH(finite_rgb(one("albedo", Params::List{1.0, 1.0, 1e300}), "albedo", RGB(1.0f)),
                      names("albedo", "must be finite"));
    CHECK_THROWS_WITH(finite_rgb(one("albedo", Params::List{1.0, 1.0}), "albedo", RGB(1.0f)),
                      names("albedo", "must be a colour (one number or a list of 3)"));
    CHECK_THROWS_WITH(finite_rgb(one("albedo", std::string("red")), "albedo", RGB(1.0f)),
                      names("albedo", "must be a colour (one number or a list of 3), not a string"));
}
