#include <rtlab/core/error.hpp>
#include <rtlab/shading/light.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rtlab;

namespace {
std::shared_ptr<Light> make(const std::string& name, Params p = {}) {
    static const LightRegistry registry = make_light_registry();
    return registry.create(name, std::move(p));
}
std::string error_of(const std::string& name, Params p) {
    try {
        make(name, std::move(p));
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST_CASE("every built-in light is registered and rejects unknown parameters", "[light]") {
    const LightRegistry r = make_light_registry();
    CHECK(r.names() == std::vector<std::string>{"ambient", "area", "directional", "point", "spot"});
    for (const auto& name : r.names()) {
        INFO(name);
        CHECK_FALSE(r.doc(name).empty());
        Params p;
        p.set("intensty", 1.0);
        const std::string e = error_of(name, p);
        CHECK(e.find("light '" + name + "'") != std::string::npos);
        CHECK(e.find("intensty") != std::string::npos);
        Params neg;
        neg.set("intensity", Params::List{1.0, -1.0, 1.0});
        CHECK(error_of(name, neg).find("'intensity'") != std::string::npos);
    }
    Params parallel;
    parallel.set("edge_u", Params::List{1, 0, 0}).set("edge_v", Params::List{2, 0, 0});
    CHECK(error_of("area", parallel).find("'edge_v'") != std::string::npos);
    Params zero;
    zero.set("direction", Params::List{0, 0, 0});
    CHECK(error_of("directional", zero).find("'direction'") != std::string::npos);
    Params wide;
    wide.set("cone_angle", 20.0).set("falloff", 25.0);
    CHECK(error_of("spot", wide).find("'falloff'") != std::string::npos);
    Params many;
    many.set("samples", 65.0);
    CHECK(error_of("area", many).find("'samples'") != std::string::npos);
}

TEST_CASE("a point light falls off with the square of distance only in the physical convention", "[light]") {
    Params p;
    p.set("position", Params::List{0, 4, 0}).set("intensity", 8.0);
    const auto light = make("point", p);
    const LightSample s = light->sample(Point3(0.0f), 0, {}, Convention::physical);
    CHECK(s.wi.y == Approx(1.0f));
    CHECK(s.arriving.g == Approx(0.5f));
    CHECK(light->sample(Point3(0.0f), 0, {}, Convention::classic).arriving.g == Approx(8.0f));
    // At the light itself: no direction, nothing arrives, nothing infinite.
    const LightSample at = light->sample(Point3(0, 4, 0), 0, {}, Convention::physical);
    CHECK(at.arriving.is_black());
    CHECK(is_finite(at.wi));
}

TEST_CASE("a spot light is full inside its cone, smooth in the falloff band and dark outside", "[light]") {
    Params p;
    p.set("position", Params::List{0, 1, 0}).set("cone_angle", 30.0).set("falloff", 10.0);
    const auto spot = make("spot", p);
    auto at = [&](float degrees) {
        const float t = degrees * kPi / 180.0f;
        return spot->sample(Point3(std::sin(t), 1.0f - std::cos(t), 0.0f), 0, {}, Convention::physical).arriving.g;
    };
    CHECK(at(0.0f) == Approx(1.0f));
    CHECK(at(19.9f) == Approx(1.0f));
    CHECK(at(30.1f) == 0.0f);
    CHECK(at(89.0f) == 0.0f);
    float last = 1.0f;
    for (float a = 20.5f; a < 30.0f; a += 0.5f) {
        const float v = at(a);
        CHECK(v < last);
        CHECK(v > 0.0f);
        last = v;
    }
}

TEST_CASE("an area light converges to the analytic irradiance of a square and is dark behind", "[light]") {
    // A unit square at height 1 centred above the origin, facing down, radiance 1 (intensity = L A = 1).
    // Below its centre, E / (pi L) is four corner configuration factors with X = Y = 0.5 (Howell's catalogue).
    const double X = 0.5, Y = 0.5;
    const double corner = (X / std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) +
                           Y / std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y))) /
                          (2.0 * kPi);
    const double expected_e_over_pi = 4.0 * corner;  // E / pi = L F
    Params p;
    p.set("corner", Params::List{-0.5, 1, -0.5}).set("edge_u", Params::List{1, 0, 0});
    p.set("edge_v", Params::List{0, 0, 1}).set("samples", 32.0);
    const auto light = make("area", p);
    REQUIRE(light->sample_count() == 1024);
    double sum = 0.0;
    for (int i = 0; i < 1024; ++i) {
        const Vec2 u(static_cast<float>((i * 7) % 13) / 13.0f, static_cast<float>((i * 5) % 11) / 11.0f);
        const LightSample s = light->sample(Point3(0.0f), i, u, Convention::physical);
        sum += s.arriving.g * s.wi.y;  // irradiance: arriving times cos at the receiver
    }
    CHECK(sum / kPi == Approx(expected_e_over_pi).epsilon(1e-3));
    // Above the light (behind its emitting side): nothing; two-sided: the mirror image.
    CHECK(light->sample(Point3(0, 2, 0), 0, {0.5f, 0.5f}, Convention::physical).arriving.is_black());
    p.set("two_sided", true);
    CHECK(make("area", p)->sample(Point3(0, 2, 0), 0, {0.5f, 0.5f}, Convention::physical).arriving.g > 0.0f);
}

TEST_CASE("directional and ambient lights", "[light]") {
    Params d;
    d.set("direction", Params::List{0, -2, 0}).set("intensity", 3.0);
    const LightSample s = make("directional", d)->sample(Point3(1e6f), 0, {}, Convention::physical);
    CHECK(s.at_infinity);
    CHECK(s.wi.y == Approx(1.0f));
    CHECK(s.arriving.g == 3.0f);
    Params a;
    a.set("intensity", 0.2);
    const auto ambient = make("ambient", a);
    CHECK(ambient->sample_count() == 0);
    CHECK(ambient->ambient().g == 0.2f);
}
