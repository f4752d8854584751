#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// A texture that is not constant: its eval tells the lookups apart.
class UvTexture final : public Texture {
public:
    RGB eval(const TextureLookup& q) const override { return {q.uv.x, q.uv.y, 0.0f}; }
};

Params with(Params::Value value) {
    Params p;
    p.set("albedo", std::move(value));
    p.set_context("material 'plastic'");
    return p;
}

auto names_albedo(const std::string& problem) { return Contains("material 'plastic': parameter 'albedo' " + problem); }
}  // namespace

TEST_CASE("texture_param reads a constant from one number or three", "[texture_param]") {
    const auto grey = texture_param(with(0.25), "albedo", RGB(1.0f));
    REQUIRE(grey->constant() != nullptr);
    CHECK(*grey->constant() == RGB(0.25f));
    CHECK(grey->eval(TextureLookup{{7.0f, -3.0f}, {1.0f, 2.0f, 3.0f}, {0.0f, 1.0f, 0.0f}}) == RGB(0.25f));
    const auto colour = texture_param(with(Params::List{0.1, 0.2, 0.3}), "albedo", RGB(1.0f));
    REQUIRE(colour->constant() != nullptr);
    CHECK(*colour->constant() == RGB(0.1f, 0.2f, 0.3f));
    // Negative or large values are the caller's to judge; only non-finite ones are refused here.
    CHECK(*texture_param(with(-2.0), "albedo", RGB(1.0f))->constant() == RGB(-2.0f));
    CHECK(*texture_param(with(3e38), "albedo", RGB(1.0f))->constant() == RGB(3e38f));
}

TEST_CASE("texture_param falls back to a constant when the key is absent", "[texture_param]") {
    Params p;
    const auto c = texture_param(p, "albedo", RGB(0.5f, 0.6f, 0.7f));
    REQUIRE(c->constant() != nullptr);
    CHECK(*c->constant() == RGB(0.5f, 0.6f, 0.7f));
    const auto g = texture_param(p, "roughness", 0.3f);
    REQUIRE(g->constant() != nullptr);
    CHECK(*g->constant() == RGB(0.3f));
    CHECK(p.names().empty());
}

TEST_CASE("texture_param returns a texture object as given and marks the key as read", "[texture_param]") {
    const auto uv = std::make_shared<UvTexture>();
    Params p;
    p.set_object<Texture>("albedo", uv);
    const auto t = texture_param(p, "albedo", RGB(1.0f));
    CHECK(t.get() == uv.get());
    CHECK(t->constant() == nullptr);
    CHECK(t->eval(TextureLookup{{0.25f, 0.75f}, {}, {}}) == RGB(0.25f, 0.75f, 0.0f));
    CHECK_NOTHROW(p.check_all_used());
    // A pointer to const texture is accepted as well.
    Params q;
    q.set_object<const Texture>("albedo", std::shared_ptr<const Texture>(uv));
    CHECK(texture_param(q, "albedo", 0.0f).get() == uv.get());
    // An unread key is still reported by check_all_used.
    Params unread = with(1.0);
    CHECK_THROWS_WITH(unread.check_all_used(), Contains("'albedo'"));
    texture_param(unread, "albedo", 0.0f);
    CHECK_NOTHROW(unread.check_all_used());
}

TEST_CASE("texture_param refuses non-finite constants and other kinds of value", "[texture_param]") {
    CHECK_THROWS_AS(texture_param(with(kNaN), "albedo", RGB(1.0f)), Error);
    CHECK_THROWS_WITH(texture_param(with(kNaN), "albedo", RGB(1.0f)), names_albedo("must be finite"));
    CHECK_THROWS_WITH(texture_param(with(Params::List{0.0, -HUGE_VAL, 0.0}), "albedo", RGB(1.0f)),
                      names_albedo("must be finite"));
    CHECK_THROWS_WITH(texture_param(with(1e39), "albedo", 1.0f), names_albedo("must be finite"));  // beyond float
    const std::string expected = "must be a colour (one number or a list of 3) or a texture, not ";
    CHECK_THROWS_WITH(texture_param(with(std::string("wood")), "albedo", RGB(1.0f)),
                      names_albedo(expected + "a string"));
    CHECK_THROWS_WITH(texture_param(with(true), "albedo", RGB(1.0f)), names_albedo(expected + "a boolean"));
    CHECK_THROWS_WITH(texture_param(with(Params::List{1.0, 2.0}), "albedo", RGB(1.0f)),
                      names_albedo(expected + "a list of 2 numbers"));
    CHECK_THROWS_WITH(texture_param(with(Params::List{}), "albedo", RGB(1.0f)),
                      names_albedo(expected + "a list of 0 numbers"));
    CHECK_THROWS_WITH(texture_param(with(Params::List{1, 2, 3, 4}), "albedo", RGB(1.0f)),
                      names_albedo(expected + "a list of 4 numbers"));
    Params other;
    other.set_context("material 'plastic'");
    other.set_object<int>("albedo", std::make_shared<int>(3));
    CHECK_THROWS_WITH(texture_param(other, "albedo", RGB(1.0f)), names_albedo(expected + "an object of another type"));
    Params null;
    null.set_context("material 'plastic'");
    null.set_object<Texture>("albedo", std::shared_ptr<Texture>());
    CHECK_THROWS_WITH(texture_param(null, "albedo", RGB(1.0f)), names_albedo("is a null texture"));
}

TEST_CASE("make_constant_texture exposes its colour and gives it for every lookup", "[texture_param]") {
    const auto t = make_constant_texture(RGB(0.0f, 2.0f, -1.0f));
    REQUIRE(t->constant() != nullptr);
    CHECK(*t->constant() == RGB(0.0f, 2.0f, -1.0f));
    CHECK(t->eval(TextureLookup{}) == RGB(0.0f, 2.0f, -1.0f));
    CHECK(t->eval(TextureLookup{{1e30f, -1e30f}, {}, {}}) == RGB(0.0f, 2.0f, -1.0f));
    // The "solid" texture is the same kind of constant.
    const auto solid = make_texture_registry().create("solid", Params{}.set("color", 0.75));
    REQUIRE(solid->constant() != nullptr);
    CHECK(*solid->constant() == RGB(0.75f));
    CHECK(make_texture_registry().create("checker", Params{})->constant() == nullptr);
}

TEST_CASE("scalar is the channel mean and exact for grey", "[texture_param]") {
    CHECK(scalar(RGB(0.0f, 0.5f, 1.0f)) == 0.5f);
    CHECK(scalar(RGB(0.3f, 0.0f, 0.0f)) == Approx(0.1f).epsilon(1e-7));
    // Grey values come back exactly, over many magnitudes, including subnormals and the largest float
    // (whose triple a float sum would overflow).
    const float hard[] = {
        0.1f,  1.0f / 3.0f, 0.7f, 1e-40f, std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max(),
        -0.3f, 16777215.0f};
    for (float x : hard) CHECK(scalar(RGB(x)) == x);
    Rng rng(5);
    int inexact = 0;
    for (int i = 0; i < 100000; ++i) {
        const float x = static_cast<float>(std::ldexp(rng.uniform(), static_cast<int>(rng.uniform() * 60.0) - 30));
        inexact += scalar(RGB(x)) == x ? 0 : 1;
    }
    CHECK(inexact == 0);
}
