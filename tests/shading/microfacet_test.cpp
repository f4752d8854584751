// The microfacet distributions, their Smith masking functions and the Cook-Torrance BRDF built on them,
// checked against the integrals that define them and against closed forms.
#include <rtlab/core/error.hpp>
#include <rtlab/shading/brdf.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "quadrature.hpp"

using namespace rtlab;
using rtlab::test::albedo;
using rtlab::test::direction;

namespace {
const std::vector<MicrofacetModel> kModels = {MicrofacetModel::ggx, MicrofacetModel::beckmann};
const char* name(MicrofacetModel m) { return m == MicrofacetModel::ggx ? "ggx" : "beckmann"; }

CookTorranceBrdf mirror_lobe(MicrofacetModel model, float roughness) {
    return {RGB(0.0f), RGB(1.0f), MicrofacetDistribution::from_roughness(model, roughness), Fresnel::one()};
}
}  // namespace

TEST_CASE("microfacet distributions integrate to one over projected area", "[microfacet]") {
    // The integral of D(m) cos(theta_m) over the hemisphere, on the grid that crowds rings near the normal
    // (1024 x 512) down to the narrowest lobe, and on a plain 256 x 512 theta-phi grid where that grid
    // resolves the lobe.
    for (MicrofacetModel model : kModels) {
        for (float alpha : {1e-3f, 0.01f, 0.1f, 0.3f, 0.6f, 1.0f}) {
            const MicrofacetDistribution d(model, alpha);
            const auto projected = [&](const Vec3& m) { return static_cast<double>(d.d(m)) * m.z; };
            const double about_normal = test::integrate_about(projected, Vec3(0, 0, 1), 0.5 * std::numbers::pi);
            INFO(name(model) << " alpha = " << alpha << ": " << about_normal);
            CHECK(about_normal == Approx(1.0).margin(1e-3));
            if (alpha >= 0.1f) CHECK(test::integrate_hemisphere(projected) == Approx(1.0).margin(1e-3));
        }
    }
}

TEST_CASE("Smith G1 lies in 0 to 1 and is 1 along the normal and 0 at the horizon", "[microfacet]") {
    int bad = 0, checked = 0;
    for (MicrofacetModel model : kModels) {
        for (float alpha : {1e-3f, 0.05f, 0.5f, 1.0f}) {
            const MicrofacetDistribution d(model, alpha);
            CHECK(d.g1({0, 0, 1}) == 1.0f);
            CHECK(d.g1({1, 0, 0}) == 0.0f);
            CHECK(d.g1({0, 0, -1}) == 0.0f);
            CHECK(d.g1_over_cos({0.6f, 0.8f, 0.0f}) == 0.0f);
            // Finite G1 / cos down to 1e-20 above the horizon (2 / (alpha sin) in the limit for GGX).
            CHECK(std::isfinite(d.g1_over_cos({1, 0, 1e-20f})));
            for (float phi : {0.0f, 1.0f}) {
                float previous = 1.0f;
                for (int i = 0; i <= 2000; ++i) {
                    const float theta = 0.5f * kPi * static_cast<float>(i) / 2000.0f;
                    const float g = d.g1(direction(theta, phi));
                    ++checked;
                    // Masking never decreases towards the horizon.
                    if (!(g >= 0.0f && g <= 1.0f && g <= previous + 1e-6f)) ++bad;
                    previous = g;
                }
            }
        }
    }
    INFO(bad << " of " << checked << " values outside [0, 1] or rising towards the horizon");
    CHECK(bad == 0);
}

TEST_CASE("Smith G1 matches hand-computed values", "[microfacet]") {
    // GGX: 2 / (1 + sqrt(1 + alpha^2 tan^2)); alpha = 0.5 at 60 degrees: 2 / (1 + sqrt(1.75)).
    const MicrofacetDistribution ggx(MicrofacetModel::ggx, 0.5f);
    CHECK(ggx.g1(direction(std::numbers::pi_v<float> / 3.0f)) == Approx(2.0 / (1.0 + std::sqrt(1.75))).epsilon(1e-6));
    // Beckmann at a = 1 / (alpha tan) = 1: 2 / (1 + erf(1) + exp(-1) / sqrt(pi)) = 0.975492.
    const MicrofacetDistribution beckmann(MicrofacetModel::beckmann, 0.5f);
    CHECK(beckmann.g1(direction(std::atan(2.0f))) ==
          Approx(2.0 / (1.0 + std::erf(1.0) + std::exp(-1.0) / std::sqrt(std::numbers::pi))).epsilon(1e-6));
    // Peak of D: 1 / (pi alpha^2) for both.
    CHECK(ggx.d({0, 0, 1}) == Approx(1.0 / (std::numbers::pi * 0.25)).epsilon(1e-6));
    CHECK(beckmann.d({0, 0, 1}) == Approx(1.0 / (std::numbers::pi * 0.25)).epsilon(1e-6));
}

TEST_CASE("Smith G1 is consistent with its distribution", "[microfacet]") {
    // The projected area of the visible microfacets equals that of the macrosurface:
    // integral of G1(v) max(0, v.m) D(m) dm = cos(theta_v) (Heitz 2014, eq. 5). This holds only for the exact
    // Smith G1 of the same D, so it also catches a G1 paired with the wrong distribution.
    for (MicrofacetModel model : kModels) {
        for (float alpha : {0.05f, 0.3f, 1.0f}) {
            const MicrofacetDistribution d(model, alpha);
            for (float theta : {0.0f, 0.5f, 1.0f, 1.3f, 1.5f, 1.55f}) {
                const Vec3 v = direction(theta, 0.4f);
                const double visible = test::integrate_about(
                    [&](const Vec3& m) { return static_cast<double>(d.d(m)) * std::max(0.0f, glm::dot(v, m)); },
                    Vec3(0, 0, 1), 0.5 * std::numbers::pi, 2048, 1024);
                INFO(name(model) << " alpha = " << alpha << " theta_v = " << theta);
                CHECK(d.g1(v) * visible == Approx(v.z).epsilon(1e-3));
            }
        }
    }
    // The other model's G1 misses by far more than that tolerance at grazing angles.
    const MicrofacetDistribution ggx(MicrofacetModel::ggx, 1.0f), beckmann(MicrofacetModel::beckmann, 1.0f);
    const Vec3 v = direction(1.3f);
    const double visible = test::integrate_about(
        [&](const Vec3& m) { return static_cast<double>(ggx.d(m)) * std::max(0.0f, glm::dot(v, m)); }, Vec3(0, 0, 1),
        0.5 * std::numbers::pi, 2048, 1024);
    CHECK(std::abs(beckmann.g1(v) * visible / v.z - 1.0) > 0.05);
}

TEST_CASE("a Cook-Torrance mirror lobe loses energy only at high roughness", "[microfacet]") {
    // White furnace with F = 1 and kd = 0: single scattering loses what reflects into the surface or
    // between microfacets, little at low roughness, and more with every step in roughness at outgoing
    // angles to 75 degrees. Nearer grazing it is not monotonic (GGX at 89.4 degrees: 0.88 at r = 0.1,
    // 0.92 at r = 0.3), as a wider lobe sends more of the light up, away from the masking near the horizon.
    const std::vector<float> roughness = {0.0f, 0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f, 1.0f};
    for (MicrofacetModel model : kModels) {
        for (float theta : {0.0f, 0.5f, 1.0f, 1.3f}) {
            double previous = 1.0 + 1e-4;
            for (float r : roughness) {
                const double a = albedo(mirror_lobe(model, r), direction(theta), 1024, 256);
                INFO(name(model) << " theta_o = " << theta << " r = " << r << " albedo = " << a);
                CHECK(a <= previous + 1e-5);
                CHECK(a <= 1.0 + 1e-4);
                if (r <= 0.2f) CHECK(a > 0.98);
                if (r <= 0.7f) CHECK(a > 0.5);
                previous = a;
            }
        }
    }
    // GGX with alpha = 1 at normal incidence: D = 1 / pi and G1 = 2 cos / (1 + cos), so the albedo is
    // the integral of (1 - 2x) / (1 - x) for x = sin^2(theta_h) in [0, 1/2]: exactly 1 - ln 2.
    CHECK(albedo(mirror_lobe(MicrofacetModel::ggx, 1.0f), {0, 0, 1}) == Approx(1.0 - std::log(2.0)).margin(1e-4));
}

TEST_CASE("Cook-Torrance reflects the Fresnel factor of its half vector", "[microfacet]") {
    const auto d = MicrofacetDistribution::from_roughness(MicrofacetModel::ggx, 0.5f);
    // At wo = wi = n: D(n) / 4 times F at normal incidence, 0.04 for glass.
    const CookTorranceBrdf glass(RGB(0.0f), RGB(1.0f), d, Fresnel::dielectric(1.5f));
    const float peak = 1.0f / (kPi * d.alpha() * d.alpha()) / 4.0f;
    CHECK(glass.eval({0, 0, 1}, {0, 0, 1}).g == Approx(0.04f * peak).epsilon(1e-5));
    // A conductor scales the F = 1 lobe by fresnel_conductor(wo.h) channel by channel.
    const CookTorranceBrdf gold(RGB(0.0f), RGB(1.0f), d, Fresnel::conductor(kGold));
    const CookTorranceBrdf white(RGB(0.0f), RGB(1.0f), d, Fresnel::one());
    const Vec3 wo = direction(1.2f, 0.3f), wi = direction(0.4f, 2.5f);
    const float cos_d = glm::dot(wo, glm::normalize(wo + wi));
    const RGB expected = fresnel_conductor(cos_d, kGold);
    for (int c = 0; c < 3; ++c)
        CHECK(gold.eval(wo, wi)[c] == Approx(expected[c] * white.eval(wo, wi)[c]).epsilon(1e-5));
    // With ks = 0 only the Lambert part remains.
    const CookTorranceBrdf diffuse(RGB(0.2f, 0.4f, 0.6f), RGB(0.0f), d, Fresnel::one());
    const RGB lambert = LambertBrdf(RGB(0.2f, 0.4f, 0.6f)).eval(wo, wi);
    for (int c = 0; c < 3; ++c) CHECK(diffuse.eval(wo, wi)[c] == lambert[c]);
}

TEST_CASE("invalid microfacet parameters are rejected", "[microfacet]") {
    using MD = MicrofacetDistribution;
    CHECK_THROWS_AS(MD(MicrofacetModel::ggx, 0.0f), Error);
    CHECK_THROWS_AS(MD(MicrofacetModel::beckmann, 0.5f * MD::kMinAlpha), Error);
    CHECK_THROWS_AS(MD(MicrofacetModel::ggx, 1.5f), Error);
    CHECK_THROWS_AS(MD(MicrofacetModel::beckmann, std::nanf("")), Error);
    CHECK_THROWS_AS(MD::from_roughness(MicrofacetModel::ggx, -0.1f), Error);
    CHECK_THROWS_AS(MD::from_roughness(MicrofacetModel::ggx, 1.1f), Error);
    CHECK(MD::from_roughness(MicrofacetModel::ggx, 0.0f).alpha() == MD::kMinAlpha);
    CHECK(MD::from_roughness(MicrofacetModel::ggx, 0.5f).alpha() == 0.25f);
    const MD d(MicrofacetModel::ggx, 0.5f);
    CHECK_THROWS_AS(CookTorranceBrdf(RGB(-0.1f), RGB(1.0f), d, Fresnel::one()), Error);
    CHECK_THROWS_AS(CookTorranceBrdf(RGB(0.5f), RGB(kInfinity), d, Fresnel::one()), Error);
}
