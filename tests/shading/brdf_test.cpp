#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/brdf.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

using namespace rtlab;

namespace {
Vec3 uniform_hemisphere(Rng& rng) {
    const float z = rng.uniform();
    const float phi = 2.0f * kPi * rng.uniform();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Directional albedo: integral of f(wo, wi) cos(theta_i) over the hemisphere, by Monte Carlo.
float albedo(const Brdf& f, const Vec3& wo, int n = 200000) {
    Rng rng(11);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const Vec3 wi = uniform_hemisphere(rng);
        sum += f.eval(wo, wi).g * wi.z * (2.0 * kPi);
    }
    return static_cast<float>(sum / n);
}

std::vector<std::unique_ptr<Brdf>> models() {
    std::vector<std::unique_ptr<Brdf>> m;
    m.push_back(std::make_unique<LambertBrdf>(RGB(0.8f)));
    m.push_back(std::make_unique<PhongBrdf>(RGB(0.3f), RGB(0.6f), 40.0f));
    m.push_back(std::make_unique<BlinnPhongBrdf>(RGB(0.3f), RGB(0.6f), 40.0f));
    return m;
}
}  // namespace

TEST_CASE("Lambert integrates to its albedo", "[brdf]") {
    const LambertBrdf f(RGB(1.0f));
    CHECK(albedo(f, {0, 0, 1}) == Approx(1.0f).epsilon(0.01));
}

TEST_CASE("BRDFs are reciprocal and black below the surface", "[brdf]") {
    Rng rng(3);
    for (const auto& f : models()) {
        for (int i = 0; i < 1000; ++i) {
            const Vec3 a = uniform_hemisphere(rng), b = uniform_hemisphere(rng);
            const RGB ab = f->eval(a, b), ba = f->eval(b, a);
            REQUIRE(ab.g == Approx(ba.g).epsilon(1e-4));
            REQUIRE(f->eval(a, Vec3(b.x, b.y, -b.z)).is_black());
        }
    }
}

TEST_CASE("normalised Phong and Blinn-Phong do not create energy", "[brdf]") {
    // kd + ks = 0.9 < 1: the directional albedo stays below 1 at every outgoing angle (a few percent of
    // Monte Carlo noise allowed), including grazing ones where unnormalised models overshoot.
    for (const auto& f : models()) {
        for (float theta : {0.0f, 0.5f, 1.0f, 1.4f, 1.55f}) {
            const Vec3 wo(std::sin(theta), 0.0f, std::cos(theta));
            const float a = albedo(*f, wo, 100000);
            INFO("theta = " << theta << " albedo = " << a);
            CHECK(a < 1.0f + 0.03f);
            CHECK(a > 0.0f);
        }
    }
}

TEST_CASE("Phong lobe peaks at the mirror direction", "[brdf]") {
    const PhongBrdf f(RGB(0.0f), RGB(1.0f), 100.0f);
    const Vec3 wo = glm::normalize(Vec3(0.5f, 0.0f, 1.0f));
    const Vec3 mirror(-wo.x, -wo.y, wo.z);
    const float peak = f.eval(wo, mirror).g;
    CHECK(peak == Approx(102.0f / (2.0f * kPi)).epsilon(1e-4));
    CHECK(f.eval(wo, glm::normalize(mirror + Vec3(0.1f, 0.0f, 0.0f))).g < peak);
}

TEST_CASE("invalid exponents are rejected", "[brdf]") {
    CHECK_THROWS_AS(PhongBrdf(RGB(0.5f), RGB(0.5f), -1.0f), Error);
    CHECK_THROWS_AS(BlinnPhongBrdf(RGB(0.5f), RGB(0.5f), std::nanf("")), Error);
}
