// Properties of every sampled material beyond its distribution: sample() agrees with eval() and pdf(),
// albedo <= 1 in importance mode (= 1 for the lossless smooth ones), reciprocity, and the generalised
// reciprocity of transmission in radiance mode; by the checks of rtlab::shading_testing.
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/shading_testing/bsdf_check.hpp>

#include <catch2/catch.hpp>

#include "sampled_material_cases.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace rtlab;
using namespace rtlab::test;
using namespace rtlab::shading_testing;

namespace {

std::vector<float> cosines_of(const MaterialCase& m) { return m.transmits ? dielectric_cosines() : opaque_cosines(); }

}  // namespace

TEST_CASE("sample gives the value and pdf that eval and pdf give for its direction", "[shading][sampling]") {
    std::uint64_t stream = 0;
    for (const MaterialCase& m : glossy_cases()) {
        const SurfaceTerms t = m.material->terms(TextureLookup{});
        for (float c : cosines_of(m))
            for (TransportMode mode : {TransportMode::radiance, TransportMode::importance}) {
                Rng rng(0xc0ffeeULL, ++stream);
                const ConsistencyResult r =
                    sample_consistency(*m.material, t, incident(c), mode, rng, 2000 / kSampleScale);
                INFO(m.label << " cos_o " << c << " mode " << int(mode) << ": " << r.first_bad);
                CHECK(r.checked > 0);
                CHECK(r.bad_pdf == 0);
                CHECK(r.bad_value == 0);
            }
    }
}

TEST_CASE("albedo never exceeds 1 in importance mode and is 1 for lossless smooth materials", "[shading][sampling]") {
    std::vector<MaterialCase> cases = glossy_cases();
    // The energy-conserving limits of each model: kd + ks = 1, white metal-like lobes.
    cases.push_back({"phong kd 0.5 ks 0.5 e 1",
                     make_material("phong", Params().set("kd", 0.5).set("ks", 0.5).set("exponent", 1.0))});
    cases.push_back({"blinn-phong kd 0.5 ks 0.5 e 10",
                     make_material("blinn-phong", Params().set("kd", 0.5).set("ks", 0.5).set("exponent", 10.0))});
    cases.push_back({"ashikhmin-shirley rd 1 rs 1",
                     make_material("ashikhmin-shirley", Params().set("rd", 1.0).set("rs", 1.0).set("nu", 10.0))});
    cases.push_back({"lambert albedo 1", make_material("lambert", Params().set("albedo", 1.0))});
    // Cook-Torrance with a Lambert base is not energy conserving by design (the 1982 model does not weigh kd
    // by 1 - F: brdf.hpp); its lobe alone is, with kd = 0.
    cases.push_back({"cook-torrance ggx kd 0 r 0.3", make_material("cook-torrance", Params().set("roughness", 0.3))});
    cases.push_back({"cook-torrance ggx kd 0 r 0.01", make_material("cook-torrance", Params().set("roughness", 0.01))});
    for (const MaterialCase& m : cases) {
        if (m.label.rfind("cook-torrance ggx r", 0) == 0) continue;
        const SurfaceTerms t = m.material->terms(TextureLookup{});
        // Under the sanitizers (ten times slower) normal and grazing incidence only.
        const std::vector<float> cosines =
            kSampleScale > 1 ? std::vector<float>{1.0f, 0.05f} : std::vector<float>{1.0f, 0.5f, 0.05f, -0.3f};
        for (float c : cosines) {
            const double a = directional_albedo(*m.material, t, incident(c), TransportMode::importance);
            INFO(m.label << " cos_o " << c << " albedo " << a);
            CHECK(a <= 1.0 + 2e-3);
            if (m.label == "lambert albedo 1") CHECK(a == Approx(1.0).margin(1e-3));
        }
    }
    // Lossless smooth materials: everything is reflected or refracted, from either side and beyond the
    // critical angle too.
    const auto glass = make_material("glass", {});
    const auto mirror = make_material("mirror", {});
    for (const auto& m : {glass, mirror}) {
        const SurfaceTerms t = m->terms(TextureLookup{});
        for (float c : dielectric_cosines()) {
            INFO("cos_o " << c);
            CHECK(directional_albedo(*m, t, incident(c), TransportMode::importance) == Approx(1.0).margin(1e-3));
        }
    }
}

TEST_CASE("the reflection models are reciprocal on both sides", "[shading][sampling]") {
    // Pairs on one side (both above or both below: the opaque models are two-sided, the dielectric's
    // reflection too) and across (the dielectric's transmission, in its generalised form).
    Rng rng(0xbeefULL, 7);
    for (const MaterialCase& m : glossy_cases()) {
        const ReciprocityResult r = reciprocity(*m.material, m.material->terms(TextureLookup{}), rng, 800);
        INFO(m.label << ": " << r.compared << " compared; " << r.first_bad);
        CHECK(r.compared > 0);
        CHECK(r.failed == 0);
    }
}

TEST_CASE("rough transmission obeys the generalised reciprocity and its adjoint", "[shading][sampling]") {
    // f(wi -> wo) / n_o^2 = f(wo -> wi) / n_i^2 across the interface, and importance mode its adjoint, into
    // glass and out of it into a bubble (the dense side outside).
    Rng rng(0xd1e1ULL, 3);
    for (double r : {0.05, 0.3, 0.9})
        for (bool bubble : {false, true}) {
            const auto m = make_material(
                "rough-dielectric",
                Params().set("roughness", r).set("ior", bubble ? 1.0 : 1.5).set("ior_outside", bubble ? 1.5 : 1.0));
            const ReciprocityResult result = reciprocity(*m, m->terms(TextureLookup{}), rng, 2000);
            INFO("roughness " << r << " bubble " << bubble << ": " << result.compared << " compared; "
                              << result.first_bad);
            CHECK(result.compared > 1000);
            CHECK(result.failed == 0);
        }
}

TEST_CASE("smooth glass scales radiance by the squared ratio of indices across the interface", "[shading][sampling]") {
    const auto glass = make_material("glass", {});
    const SurfaceTerms t = glass->terms(TextureLookup{});
    for (float c : {0.9f, 0.3f, -0.9f}) {
        const Vec3 wo = incident(c);
        // uc near 1 picks transmission (the lobes are ordered reflection, transmission).
        const auto rad = glass->sample(t, wo, 0.999f, Vec2(0.5f), TransportMode::radiance);
        const auto imp = glass->sample(t, wo, 0.999f, Vec2(0.5f), TransportMode::importance);
        REQUIRE(rad);
        REQUIRE(imp);
        REQUIRE((rad->flags & kLobeTransmission));
        const float n_o = c > 0.0f ? 1.0f : 1.5f, n_i = c > 0.0f ? 1.5f : 1.0f;
        INFO("cos_o " << c);
        CHECK(imp->value.g == Approx(1.0f).epsilon(1e-5));
        CHECK(rad->value.g == Approx((n_o / n_i) * (n_o / n_i)).epsilon(1e-5));
        CHECK(rad->wi.z * wo.z < 0.0f);
    }
}
