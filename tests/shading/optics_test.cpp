#include <rtlab/shading/optics.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace rtlab;

namespace {
Vec3 incident(float theta) { return {std::sin(theta), 0.0f, -std::cos(theta)}; }  // towards a +z surface
const Normal3 up{0, 0, 1};
}  // namespace

TEST_CASE("reflection keeps the angle and flips the normal component", "[optics]") {
    for (float theta : {0.0f, 0.3f, 1.0f, 1.5f}) {
        const Vec3 r = reflect(incident(theta), up);
        CHECK(r.x == Approx(std::sin(theta)));
        CHECK(r.z == Approx(std::cos(theta)));
        CHECK(glm::length(r) == Approx(1.0f));
    }
}

TEST_CASE("refraction obeys Snell's law and stays unit length", "[optics]") {
    for (float eta : {1.0f / 1.5f, 1.0f / 1.33f, 1.2f}) {
        for (float theta : {0.0f, 0.2f, 0.5f, 0.7f}) {
            const auto t = refract(incident(theta), up, eta);
            REQUIRE(t);
            const float sin_t = std::hypot(t->x, t->y);
            CHECK(sin_t == Approx(eta * std::sin(theta)).margin(1e-6));
            CHECK(glm::length(*t) == Approx(1.0f));
            CHECK(t->z < 0.0f);  // continues through the surface
        }
    }
    // Normal incidence passes straight through.
    const auto straight = refract({0, 0, -1}, up, 1.0f / 1.5f);
    REQUIRE(straight);
    CHECK(straight->z == Approx(-1.0f));
}

TEST_CASE("total internal reflection beyond the critical angle", "[optics]") {
    const float eta = 1.5f;  // glass to air
    const float critical = std::asin(1.0f / eta);
    CHECK(refract(incident(critical - 0.01f), up, eta));
    CHECK_FALSE(refract(incident(critical + 0.01f), up, eta));
    CHECK(fresnel_dielectric(std::cos(critical + 0.01f), eta) == 1.0f);
    CHECK(fresnel_schlick(std::cos(critical + 0.01f), eta) == 1.0f);
}

TEST_CASE("Fresnel reflectance at normal and grazing incidence", "[optics]") {
    // Air to glass at normal incidence: ((1 - 1.5) / (1 + 1.5))^2 = 0.04.
    CHECK(fresnel_dielectric(1.0f, 1.0f / 1.5f) == Approx(0.04f).epsilon(1e-5));
    CHECK(fresnel_dielectric(1.0f, 1.5f) == Approx(0.04f).epsilon(1e-5));
    CHECK(fresnel_schlick(1.0f, 1.0f / 1.5f) == Approx(0.04f).epsilon(1e-5));
    CHECK(fresnel_dielectric(0.0f, 1.0f / 1.5f) == Approx(1.0f));
    CHECK(fresnel_dielectric(1.0f, 1.0f) == Approx(0.0f).margin(1e-7));  // no interface, no reflection
    // Brewster's angle: the p-polarised part vanishes, so R = r_s^2 / 2 ~= 0.0739 for n = 1.5.
    const float brewster = std::atan(1.5f);
    CHECK(fresnel_dielectric(std::cos(brewster), 1.0f / 1.5f) == Approx(0.0739f).epsilon(0.01));
}

TEST_CASE("Schlick stays within a few percent of exact Fresnel", "[optics]") {
    float worst = 0.0f;
    for (int i = 0; i <= 1000; ++i) {
        const float cos_i = static_cast<float>(i) / 1000.0f;
        for (float eta : {1.0f / 1.5f, 1.5f})
            worst = std::max(worst, std::abs(fresnel_schlick(cos_i, eta) - fresnel_dielectric(cos_i, eta)));
    }
    INFO("largest |Schlick - Fresnel| = " << worst);
    CHECK(worst < 0.06f);
    CHECK(worst > 0.0f);
}
