#include <rtlab/core/error.hpp>
#include <rtlab/shading/optics.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

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

namespace {
// |r_s|^2 and |r_p|^2 straight from the Fresnel equations with a complex index, in double: the reference the
// real-arithmetic fresnel_conductor must reproduce.
double fresnel_complex(double cos_i, double eta, double k) {
    const std::complex<double> n(eta, k);
    const double sin2 = 1.0 - cos_i * cos_i;
    const std::complex<double> n_cos_t = std::sqrt(n * n - sin2);  // n cos(theta_t), Re >= 0
    const std::complex<double> r_s = (cos_i - n_cos_t) / (cos_i + n_cos_t);
    const std::complex<double> r_p = (n * n * cos_i - n_cos_t) / (n * n * cos_i + n_cos_t);
    return 0.5 * (std::norm(r_s) + std::norm(r_p));
}
}  // namespace

TEST_CASE("conductor Fresnel with k = 0 is the dielectric Fresnel", "[optics]") {
    // fresnel_conductor takes n_t / n_i, fresnel_dielectric n_i / n_t; both sides of the critical angle. In
    // float, 1 / eta is eta's reciprocal only to half an ulp, which moves R by more than 1e-5 within 2e-3 of
    // the critical angle (a square-root singularity in cos_i) and at grazing incidence for eta within 1e-4
    // of 1 (where R depends on eta - 1). Those cases are left to the complex-index test below, where each
    // function is compared with the exact value for the index it was given.
    float worst = 0.0f;
    for (float eta : {1.5f, 1.33f, 2.4f, 1.0f / 1.5f, 1.0f / 1.33f, 1.05f, 1.0f / 1.05f}) {
        const float cos_critical = eta < 1.0f ? std::sqrt(1.0f - eta * eta) : -1.0f;
        for (int i = 0; i <= 1000; ++i) {
            const float cos_i = static_cast<float>(i) / 1000.0f;
            if (std::abs(cos_i - cos_critical) < 2e-3f) continue;
            worst =
                std::max(worst, std::abs(fresnel_conductor(cos_i, eta, 0.0f) - fresnel_dielectric(cos_i, 1.0f / eta)));
        }
    }
    INFO("largest difference " << worst);
    CHECK(worst < 1e-5f);
    // Total internal reflection beyond asin(1 / 1.5), from inside the glass.
    const float critical = std::asin(1.0f / 1.5f);
    CHECK(fresnel_conductor(std::cos(critical + 0.01f), 1.0f / 1.5f, 0.0f) == 1.0f);
    CHECK(fresnel_conductor(std::cos(critical - 0.01f), 1.0f / 1.5f, 0.0f) < 1.0f);
    CHECK(fresnel_conductor(1.0f, 1.5f, 0.0f) == Approx(0.04f).epsilon(1e-5));
}

TEST_CASE("conductor Fresnel at normal incidence is ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2)", "[optics]") {
    for (const ComplexIor& metal : {kGold, kSilver, kCopper, kAluminium}) {
        const RGB r = fresnel_conductor(1.0f, metal);
        for (int c = 0; c < 3; ++c) {
            const double n = metal.eta[c], k = metal.k[c];
            CHECK(r[c] == Approx(((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k)).epsilon(1e-5));
        }
    }
    // Gold by hand, red channel (n = 0.14, k = 3.697 at 659.5 nm): (0.7396 + 13.667809) / (1.2996 + 13.667809).
    CHECK(fresnel_conductor(1.0f, kGold).r == Approx(14.407409 / 14.967409).epsilon(1e-5));
    // The presets look like their metals: gold and copper redder than blue, silver and aluminium > 0.9.
    CHECK(fresnel_conductor(1.0f, kGold).r > fresnel_conductor(1.0f, kGold).g);
    CHECK(fresnel_conductor(1.0f, kGold).g > fresnel_conductor(1.0f, kGold).b + 0.3f);
    CHECK(fresnel_conductor(1.0f, kCopper).r > fresnel_conductor(1.0f, kCopper).b + 0.3f);
    CHECK(fresnel_conductor(1.0f, kSilver).b > 0.95f);
    CHECK(fresnel_conductor(1.0f, kAluminium).g > 0.9f);
}

TEST_CASE("conductor Fresnel matches the complex Fresnel equations at every angle", "[optics]") {
    double worst = 0.0;
    for (const ComplexIor& metal : {kGold, kSilver, kCopper, kAluminium, ComplexIor{RGB(1.0f), RGB(0.5f)}}) {
        for (int c = 0; c < 3; ++c) {
            for (int i = 0; i <= 1000; ++i) {
                const float cos_i = static_cast<float>(i) / 1000.0f;
                const double r = fresnel_conductor(cos_i, metal.eta[c], metal.k[c]);
                worst = std::max(worst, std::abs(r - fresnel_complex(cos_i, metal.eta[c], metal.k[c])));
                REQUIRE(r >= 0.0);
                REQUIRE(r <= 1.0);
            }
        }
        CHECK(fresnel_conductor(0.0f, metal.eta.g, metal.k.g) == 1.0f);  // grazing: total reflection
    }
    // Dielectrics (k = 0) through both functions, including eta within 1e-4 of 1 at grazing incidence and
    // the critical angles of eta < 1.
    for (float eta : {1.5f, 1.0f / 1.5f, 1.33f, 1.0f / 1.33f, 1.0001f, 1.0f / 1.0001f}) {
        for (int i = 0; i <= 1000; ++i) {
            const float cos_i = static_cast<float>(i) / 1000.0f;
            worst = std::max(worst, std::abs(fresnel_conductor(cos_i, eta, 0.0f) - fresnel_complex(cos_i, eta, 0.0)));
            const float inverse = 1.0f / eta;  // what fresnel_dielectric is given, compared at that same index
            worst = std::max(worst,
                             std::abs(fresnel_dielectric(cos_i, inverse) - fresnel_complex(cos_i, 1.0 / inverse, 0.0)));
        }
    }
    INFO("largest difference from the complex-index reference " << worst);
    CHECK(worst < 1e-5);
}

TEST_CASE("Fresnel factors of a specular lobe", "[optics]") {
    CHECK(Fresnel::dielectric(1.5f).eval(1.0f).g == Approx(0.04f).epsilon(1e-5));
    // Light from inside the glass (relative index 1 / 1.5) past the critical angle is totally reflected.
    CHECK(Fresnel::dielectric(1.0f / 1.5f).eval(std::cos(std::asin(1.0f / 1.5f) + 0.01f)).g == 1.0f);
    CHECK(Fresnel::conductor(kGold).eval(0.5f) == fresnel_conductor(0.5f, kGold));
    CHECK(Fresnel::one().eval(0.3f) == RGB(1.0f));
    CHECK_THROWS_AS(Fresnel::dielectric(0.0f), Error);
    CHECK_THROWS_AS(Fresnel::conductor({RGB(0.2f), RGB(-1.0f)}), Error);
    CHECK_THROWS_AS(Fresnel::conductor({RGB(std::nanf("")), RGB(1.0f)}), Error);
}
