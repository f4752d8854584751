// Photons leaving lights (Emitter::sample_le): where they start, the directions against their densities (chi-square),
// and the power each stands for, whose mean is the light's emitted power (exactly where the sampling makes every
// photon alike, within 3 standard errors where it does not).
#include <rtlab/core/frame.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/emitter.hpp>
#include <rtlab/shading/environment_map.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading_testing/chi_square.hpp>
#include <rtlab/shading_testing/statistics.hpp>

#include "sample_scale.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

using namespace rtlab;

namespace rtlab::test {
using shading_testing::chi_square_test;
using shading_testing::ChiSquareResult;
using shading_testing::sidak_level;
}  // namespace rtlab::test

namespace {

// Chi-square tests in this file, for the Sidak-corrected level (family-wise 1e-3).
constexpr int kChiSquareTests = 5;
const double kLevel = test::sidak_level(1e-3, kChiSquareTests);

std::shared_ptr<const Light> make_light(const std::string& name, Params p) {
    static const LightRegistry registry = make_light_registry();
    return registry.create(name, std::move(p));
}

EmitterShape quad(const Point3& c, const Vec3& u, const Vec3& v) {
    EmitterShape s;
    s.triangles.push_back({c, c + u, c + u + v});
    s.triangles.push_back({c, c + u + v, c + v});
    return s;
}

// Chi-square of sample_le's directions against `pdf`, n draws.
test::ChiSquareResult direction_test(const Emitter& e, const SceneSphere& scene,
                                     const std::function<double(const Vec3&)>& pdf, std::uint64_t seed, int n) {
    Rng rng(seed);
    return test::chi_square_test(
        [&](Rng& g) -> std::optional<Vec3> {
            const Vec2 up = g.uniform2();
            const auto s = e.sample_le(up, g.uniform2(), scene);
            if (!s) return std::nullopt;
            return s->direction;
        },
        pdf, {}, rng, n);
}

bool same(const RGB& a, const RGB& b, float tolerance) {
    return std::abs(a.r - b.r) <= tolerance * std::abs(b.r) && std::abs(a.g - b.g) <= tolerance * std::abs(b.g) &&
           std::abs(a.b - b.b) <= tolerance * std::abs(b.b);
}

}  // namespace

TEST_CASE("An area light's photons leave its surface by the cosine with its whole power each", "[emission]") {
    const Point3 c(-0.5f, 1.0f, -0.3f);
    const Vec3 u(1.2f, 0.0f, 0.0f), v(0.0f, 0.2f, 0.7f);
    const Normal3 n = glm::normalize(glm::cross(u, v));
    const SceneSphere scene{Point3(0.0f), 3.0f};
    const int draws = 60000 / test::kSampleScale;
    for (const bool two_sided : {false, true}) {
        const AreaEmitter e(quad(c, u, v), RGB(2.0f, 1.0f, 0.5f), two_sided);
        Rng rng(11);
        for (int i = 0; i < 2000; ++i) {
            const auto s = e.sample_le(rng.uniform2(), rng.uniform2(), scene);
            REQUIRE(s);
            // On the quad, its normal the face it leaves, every photon the light's power.
            CHECK(std::abs(glm::dot(s->position - c, n)) < 1e-5f);
            CHECK(std::abs(glm::dot(s->normal, n)) == Approx(1.0f));
            CHECK(glm::dot(s->direction, s->normal) > 0.0f);
            CHECK(same(s->power, e.power(), 1e-6f));
            // The densities describe the draw: power = radiance cos / (pdf_position pdf_direction).
            const RGB from_pdfs =
                s->radiance * (glm::dot(s->direction, s->normal) / (s->pdf_position * s->pdf_direction));
            CHECK(same(from_pdfs, s->power, 1e-3f));
        }
        const test::ChiSquareResult r = direction_test(
            e, scene,
            [&](const Vec3& w) {
                const double cos = glm::dot(glm::dvec3(w), glm::dvec3(n));
                if (two_sided) return std::abs(cos) / (2.0 * kPi);
                return cos > 0.0 ? cos / kPi : 0.0;
            },
            two_sided ? 12 : 13, draws);
        INFO((two_sided ? "two-sided" : "one-sided")
             << ": chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value << " worst " << r.worst);
        CHECK(r.failure.empty());
        CHECK(r.p_value > kLevel);
        CHECK(r.pdf_integral == Approx(1.0).margin(2e-3));
    }
}

TEST_CASE("A sphere light's photons leave its surface outwards", "[emission]") {
    EmitterShape s;
    s.kind = EmitterShape::Kind::sphere;
    s.centre = Point3(1.0f, 2.0f, 3.0f);
    s.radius = 0.25f;
    const AreaEmitter e(s, RGB(4.0f), false);
    Rng rng(3);
    for (int i = 0; i < 2000; ++i) {
        const auto p = e.sample_le(rng.uniform2(), rng.uniform2(), SceneSphere{});
        REQUIRE(p);
        const Vec3 out = p->position - s.centre;
        CHECK(glm::length(out) == Approx(0.25f).epsilon(1e-5));
        CHECK(glm::dot(p->direction, out) > 0.0f);
        CHECK(same(p->power, e.power(), 1e-6f));
    }
}

TEST_CASE("A point light sends photons uniformly over the sphere", "[emission]") {
    Params p;
    p.set("position", Params::List{0.5, 1.0, -2.0}).set("intensity", Params::List{3.0, 2.0, 1.0});
    const DeltaEmitter e(make_light("point", p), 5.0f);
    const SceneSphere scene{Point3(0.0f), 5.0f};
    Rng rng(5);
    for (int i = 0; i < 1000; ++i) {
        const auto s = e.sample_le(rng.uniform2(), rng.uniform2(), scene);
        REQUIRE(s);
        CHECK(s->delta_position);
        CHECK(glm::length(s->position - Point3(0.5f, 1.0f, -2.0f)) < 1e-6f);
        CHECK(same(s->radiance, RGB(3.0f, 2.0f, 1.0f), 1e-5f));  // the intensity, whichever the direction
        CHECK(same(s->power, e.power(), 1e-5f));                 // 4 pi I
    }
    const test::ChiSquareResult r = direction_test(
        e, scene, [](const Vec3&) { return 1.0 / (4.0 * kPi); }, 17, 60000 / test::kSampleScale);
    INFO("chi2 " << r.statistic << " p " << r.p_value);
    CHECK(r.p_value > kLevel);
}

TEST_CASE("A spot light sends photons into its cone and their mean power is its power", "[emission]") {
    Params p;
    p.set("position", Params::List{0.0, 3.0, 0.0}).set("direction", Params::List{0.3, -1.0, 0.2});
    p.set("intensity", 5.0).set("cone_angle", 35.0).set("falloff", 15.0);
    const auto light = make_light("spot", p);
    const DeltaEmitter e(light, 4.0f);
    const Vec3 axis = glm::normalize(Vec3(0.3f, -1.0f, 0.2f));
    const double cos_max = std::cos(35.0 * kPi / 180.0);
    const SceneSphere scene{Point3(0.0f), 4.0f};
    Rng rng(7);
    const int n = 100000 / test::kSampleScale;
    double sum = 0.0, sum2 = 0.0;
    int inside = 0;
    for (int i = 0; i < n; ++i) {
        const auto s = e.sample_le(rng.uniform2(), rng.uniform2(), scene);
        if (!s) continue;  // the cone's very edge, where the smoothstep is 0
        inside += glm::dot(s->direction, axis) >= cos_max - 1e-5;
        const double w = s->power.r;
        sum += w;
        sum2 += w * w;
    }
    const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
    const double expected = light->power(4.0f).r;
    INFO("mean power " << mean << " +- " << se << ", the light's " << expected);
    CHECK(inside >= n - 10);
    CHECK(std::abs(mean - expected) <= 3.0 * se);
    CHECK(se < 0.01 * expected);
    // Directions uniform in the cone (the intensity's edge is in the power, not in the density), tested in the cone's
    // frame, where its edge is a circle of latitude.
    const Frame cone = Frame::from_normal(axis);
    Rng g(19);
    const test::ChiSquareResult r = test::chi_square_test(
        [&](Rng& q) -> std::optional<Vec3> {
            const Vec2 up = q.uniform2();
            const auto s = e.sample_le(up, q.uniform2(), scene);
            if (!s) return std::nullopt;  // black at the cone's very edge: a draw the density does not describe
            return cone.to_local(s->direction);
        },
        [&](const Vec3& w) { return w.z > cos_max ? 1.0 / (2.0 * kPi * (1.0 - cos_max)) : 0.0; }, {}, g,
        60000 / test::kSampleScale);
    INFO("chi2 " << r.statistic << " p " << r.p_value << " worst " << r.worst << " failure " << r.failure);
    CHECK(r.p_value > kLevel);
}

TEST_CASE("A directional light sends photons from a disk covering the scene", "[emission]") {
    Params p;
    p.set("direction", Params::List{1.0, -2.0, 0.5}).set("intensity", Params::List{2.0, 2.0, 1.0});
    const DeltaEmitter e(make_light("directional", p), 3.0f);
    const SceneSphere scene{Point3(1.0f, 0.0f, -1.0f), 3.0f};
    const Vec3 d = glm::normalize(Vec3(1.0f, -2.0f, 0.5f));
    Rng rng(9);
    float widest = 0.0f;
    for (int i = 0; i < 5000; ++i) {
        const auto s = e.sample_le(rng.uniform2(), rng.uniform2(), scene);
        REQUIRE(s);
        CHECK(s->delta_direction);
        CHECK(glm::dot(s->direction, d) == Approx(1.0f));
        // On the disk of the scene's radius, perpendicular to the light, a radius before the centre.
        const Vec3 off = s->position - scene.centre;
        CHECK(glm::dot(off, d) == Approx(-3.0f).epsilon(1e-4));
        const float across = glm::length(off - glm::dot(off, d) * d);
        CHECK(across <= 3.0f * 1.0001f);
        widest = std::max(widest, across);
        CHECK(same(s->power, RGB(2.0f, 2.0f, 1.0f) * (kPi * 9.0f), 1e-5f));
    }
    CHECK(widest > 2.9f);
}

TEST_CASE("A uniform environment sends photons from every direction with the power it is given", "[emission]") {
    const UniformEnvironment env(RGB(0.5f), 2.0f);
    const SceneSphere scene{Point3(0.0f, 1.0f, 0.0f), 2.0f};
    Rng rng(13);
    for (int i = 0; i < 2000; ++i) {
        const auto s = env.sample_le(rng.uniform2(), rng.uniform2(), scene);
        REQUIRE(s);
        const Vec3 off = s->position - scene.centre;
        CHECK(glm::dot(off, s->direction) == Approx(-2.0f).epsilon(1e-4));
        CHECK(glm::length(off - glm::dot(off, s->direction) * s->direction) <= 2.0f * 1.0001f);
        CHECK(same(s->power, env.power(), 1e-5f));
    }
    const test::ChiSquareResult r = direction_test(
        env, scene, [](const Vec3&) { return 1.0 / (4.0 * kPi); }, 23, 60000 / test::kSampleScale);
    INFO("chi2 " << r.statistic << " p " << r.p_value);
    CHECK(r.p_value > kLevel);
}

TEST_CASE("An environment map sends photons by its luminance with its power on average", "[emission]") {
    // A sky brighter above, coloured across, with a bright patch: photons come by the map's sampling, so each one's
    // power differs with the colour the luminance-based density does not follow. Their directions are sample_li's
    // reversed, whose distribution environment_map_test checks: here their density must be pdf_li's.
    Image img(32, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x) img.at(x, y) = RGB(0.2f + 0.8f * (y < 8), 0.3f + 0.02f * x, 0.5f + 0.03f * y);
    for (int y = 4; y < 6; ++y)
        for (int x = 20; x < 23; ++x) img.at(x, y) = RGB(40.0f, 30.0f, 20.0f);
    const SceneSphere scene{Point3(0.5f, -1.0f, 2.0f), 3.0f};
    const std::shared_ptr<const EnvironmentEmitter> env =
        EnvironmentMap(std::move(img), {.rotation_degrees = 30.0f}).for_scene_radius(scene.radius);
    Rng rng(29);
    const int n = 100000 / test::kSampleScale;
    double sum[3] = {0.0, 0.0, 0.0}, sum2[3] = {0.0, 0.0, 0.0};
    int missed = 0;
    for (int i = 0; i < n; ++i) {
        const Vec2 up = rng.uniform2();
        const auto s = env->sample_le(up, rng.uniform2(), scene);
        if (!s) {
            ++missed;
            continue;
        }
        const Vec3 off = s->position - scene.centre;
        REQUIRE(glm::dot(off, s->direction) == Approx(-scene.radius).epsilon(1e-4));
        REQUIRE(glm::length(off - glm::dot(off, s->direction) * s->direction) <= scene.radius * 1.0001f);
        REQUIRE(s->pdf_direction ==
                Approx(env->pdf_li(scene.centre, -s->direction, scene.centre, Normal3(0.0f))).epsilon(1e-4));
        for (int c = 0; c < 3; ++c) {
            sum[c] += s->power[c];
            sum2[c] += double(s->power[c]) * s->power[c];
        }
    }
    CHECK(missed <= n / 10000);
    const RGB expected = env->power();
    for (int c = 0; c < 3; ++c) {
        const double mean = sum[c] / n, se = std::sqrt((sum2[c] / n - mean * mean) / n);
        INFO("channel " << c << ": mean power " << mean << " +- " << se << ", the map's " << expected[c]);
        CHECK(std::abs(mean - expected[c]) <= 3.0 * se);
        CHECK(se < 0.01 * expected[c]);
    }
}
