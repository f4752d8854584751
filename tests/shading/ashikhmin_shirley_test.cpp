// Ashikhmin-Shirley (2000): symmetry about the normal when nu = nv and only then, the paper's diffuse and
// specular terms at hand-computed points, and the specular albedo at normal incidence in closed form.
#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/brdf.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "quadrature.hpp"

using namespace rtlab;
using rtlab::test::albedo;
using rtlab::test::direction;

namespace {
Vec3 rotate_z(const Vec3& v, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

// Largest relative change of f over random pairs when both directions turn about the normal, and how many
// pairs change by more than 1e-4.
std::pair<float, int> rotation_change(const Brdf& f) {
    Rng rng(7);
    float worst = 0.0f;
    int changed = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 wo = direction(1.5f * rng.uniform(), 2.0f * kPi * rng.uniform());
        // wi near the mirror direction, where the lobe is.
        const Vec3 wi =
            glm::normalize(Vec3(-wo.x, -wo.y, wo.z) + 0.2f * Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, 0));
        const float angle = 2.0f * kPi * rng.uniform();
        const float a = f.eval(wo, wi).g, b = f.eval(rotate_z(wo, angle), rotate_z(wi, angle)).g;
        const float rel = std::abs(a - b) / std::max(a, b);
        worst = std::max(worst, rel);
        if (rel > 1e-4f) ++changed;
    }
    return {worst, changed};
}
}  // namespace

TEST_CASE("Ashikhmin-Shirley with nu = nv is unchanged by rotation about the normal", "[ashikhmin-shirley]") {
    for (float n : {0.0f, 10.0f, 1000.0f}) {
        const AshikhminShirleyBrdf f(RGB(0.5f), RGB(0.3f), n, n);
        const auto [worst, changed] = rotation_change(f);
        INFO("nu = nv = " << n << ": worst relative change " << worst);
        CHECK(changed == 0);
    }
}

TEST_CASE("Ashikhmin-Shirley with nu != nv changes under rotation about the normal", "[ashikhmin-shirley]") {
    const AshikhminShirleyBrdf f(RGB(0.5f), RGB(0.3f), 10.0f, 1000.0f);
    const auto [worst, changed] = rotation_change(f);
    INFO(changed << " of 5000 pairs change by more than 1e-4, worst " << worst);
    CHECK(changed > 4000);
    CHECK(worst > 0.9f);
    // The lobe is wide along the tangent (nu = 10) and narrow along the bitangent (nv = 1000): for wo = n
    // and half vectors tilted by 0.1 rad along x or y, everything but the exponent is the same, so the
    // ratio is cos(0.1)^10 / cos(0.1)^1000.
    const auto mirror_of_n = [](const Vec3& h) { return 2.0f * h.z * h - Vec3(0, 0, 1); };
    const float along_x = f.eval({0, 0, 1}, mirror_of_n(direction(0.1f, 0.0f))).g;
    const float along_y = f.eval({0, 0, 1}, mirror_of_n(direction(0.1f, 0.5f * kPi))).g;
    const AshikhminShirleyBrdf spec_only(RGB(0.0f), RGB(0.3f), 10.0f, 1000.0f);
    const float diffuse = along_x - spec_only.eval({0, 0, 1}, mirror_of_n(direction(0.1f, 0.0f))).g;
    CHECK((along_x - diffuse) / (along_y - diffuse) == Approx(std::pow(std::cos(0.1), -990.0)).epsilon(1e-3));
}

TEST_CASE("Ashikhmin-Shirley terms match the paper at hand-computed points", "[ashikhmin-shirley]") {
    // wo = wi = n: h = n, so the specular term is sqrt((nu + 1)(nv + 1)) / (8 pi) F(1) with F(1) = rs, and
    // the diffuse term 28 rd / (23 pi) (1 - rs) (1 - 0.5^5)^2.
    const float rd = 0.6f, rs = 0.25f, nu = 3.0f, nv = 48.0f;
    const AshikhminShirleyBrdf f(RGB(rd), RGB(rs), nu, nv);
    const double spec = std::sqrt((nu + 1.0) * (nv + 1.0)) / (8.0 * std::numbers::pi) * rs;
    const double diff = 28.0 * rd / (23.0 * std::numbers::pi) * (1.0 - rs) * std::pow(1.0 - std::pow(0.5, 5), 2);
    CHECK(f.eval({0, 0, 1}, {0, 0, 1}).g == Approx(spec + diff).epsilon(1e-6));
    // Elsewhere, the diffuse term alone: the difference between rd and rd = 0.
    const Vec3 wo = direction(0.4f, 0.1f), wi = direction(1.1f, 2.0f);
    const AshikhminShirleyBrdf no_diffuse(RGB(0.0f), RGB(rs), nu, nv);
    const auto falloff = [](double c) { return 1.0 - std::pow(1.0 - 0.5 * c, 5); };
    CHECK(f.eval(wo, wi).g - no_diffuse.eval(wo, wi).g ==
          Approx(28.0 * rd / (23.0 * std::numbers::pi) * (1.0 - rs) * falloff(wo.z) * falloff(wi.z)).epsilon(1e-5));
}

TEST_CASE("Ashikhmin-Shirley specular albedo at normal incidence matches its closed form", "[ashikhmin-shirley]") {
    // rs = 1 (F = 1), wo = n: theta_i = 2 theta_h, max(cos_o, cos_i) = 1, so the albedo is
    // (n + 1) [2 (1 - 2^-(n+3)/2) / (n + 3) - (1 - 2^-(n+1)/2) / (n + 1)], below 1 for every n.
    for (double n : {0.0, 1.0, 10.0, 100.0, 1e4, 1e5}) {
        const AshikhminShirleyBrdf f(RGB(0.0f), RGB(1.0f), static_cast<float>(n), static_cast<float>(n));
        const double exact = (n + 1.0) * (2.0 * (1.0 - std::pow(2.0, -(n + 3.0) / 2.0)) / (n + 3.0) -
                                          (1.0 - std::pow(2.0, -(n + 1.0) / 2.0)) / (n + 1.0));
        INFO("n = " << n);
        CHECK(albedo(f, {0, 0, 1}) == Approx(exact).margin(1e-4));
    }
}

TEST_CASE("invalid Ashikhmin-Shirley parameters are rejected", "[ashikhmin-shirley]") {
    CHECK_THROWS_AS(AshikhminShirleyBrdf(RGB(0.5f), RGB(0.5f), -1.0f, 10.0f), Error);
    CHECK_THROWS_AS(AshikhminShirleyBrdf(RGB(0.5f), RGB(0.5f), 10.0f, kInfinity), Error);
    CHECK_THROWS_AS(AshikhminShirleyBrdf(RGB(-0.5f), RGB(0.5f), 10.0f, 10.0f), Error);
    CHECK_THROWS_AS(AshikhminShirleyBrdf(RGB(0.5f), RGB(std::nanf("")), 10.0f, 10.0f), Error);
}
