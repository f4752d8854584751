// Properties of every sampled material beyond its distribution: sample() agrees with eval() and pdf(),
// albedo <= 1 in importance mode (= 1 for the lossless smooth ones), reciprocity, and the generalised
// reciprocity of transmission in radiance mode.
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/material.hpp>

#include <catch2/catch.hpp>

#include "sampled_material_cases.hpp"
#include "sampling_stats.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace rtlab;
using namespace rtlab::test;

namespace {

std::vector<float> cosines_of(const MaterialCase& m) { return m.transmits ? dielectric_cosines() : opaque_cosines(); }

double rel_diff(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-30}); }

// The directional albedo for wo: the integral of eval |cos| (adaptive quadrature, hinted at the mirror and
// refracted directions) plus the delta lobes' weights, each found by sweeping uc over a fine grid (a delta
// lobe's value times its share of the grid is its weight, to 1 / (grid chance)).
double albedo(const Material& m, const SurfaceTerms& t, const Vec3& wo, TransportMode mode) {
    const auto f = [&](const Vec3& wi) { return double(channel_mean(m.eval(t, wo, wi, mode))) * std::abs(wi.z); };
    double total = SphereQuadrature(f, lobe_hints(wo)).integrate_sphere(12, 12);
    constexpr int kGrid = 100000;
    for (int i = 0; i < kGrid; ++i) {
        const std::optional<BsdfSample> s = m.sample(t, wo, (i + 0.5f) / kGrid, Vec2(0.5f), mode);
        if (s && (s->flags & kLobeSpecular)) total += channel_mean(s->value) / kGrid;
    }
    return total;
}

}  // namespace

TEST_CASE("sample gives the value and pdf that eval and pdf give for its direction", "[shading][sampling]") {
    std::uint64_t stream = 0;
    for (const MaterialCase& m : glossy_cases()) {
        const SurfaceTerms t = m.material->terms(TextureLookup{});
        for (float c : cosines_of(m))
            for (TransportMode mode : {TransportMode::radiance, TransportMode::importance}) {
                const Vec3 wo = incident(c);
                Rng rng(0xc0ffeeULL, ++stream);
                int checked = 0, bad_value = 0, bad_pdf = 0;
                for (int k = 0; k < 2000 / kSampleScale; ++k) {
                    const float uc = rng.uniform();
                    const Vec2 u = rng.uniform2();
                    const std::optional<BsdfSample> s = m.material->sample(t, wo, uc, u, mode);
                    if (!s || (s->flags & kLobeSpecular)) continue;
                    ++checked;
                    const float pdf = m.material->pdf(t, wo, s->wi, mode);
                    const RGB f = m.material->eval(t, wo, s->wi, mode);
                    if (rel_diff(pdf, s->pdf) > 1e-3) ++bad_pdf;
                    for (int ch = 0; ch < 3; ++ch)
                        if (rel_diff(f[ch] * std::abs(s->wi.z) / pdf, s->value[ch]) > 1e-3) {
                            ++bad_value;
                            break;
                        }
                }
                INFO(m.label << " cos_o " << c << " mode " << int(mode));
                CHECK(checked > 0);
                CHECK(bad_pdf == 0);
                CHECK(bad_value == 0);
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
            const double a = albedo(*m.material, t, incident(c), TransportMode::importance);
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
            CHECK(albedo(*m, t, incident(c), TransportMode::importance) == Approx(1.0).margin(1e-3));
        }
    }
}

TEST_CASE("the reflection models are reciprocal on both sides", "[shading][sampling]") {
    Rng rng(0xbeefULL, 7);
    for (const MaterialCase& m : glossy_cases()) {
        const SurfaceTerms t = m.material->terms(TextureLookup{});
        int compared = 0;
        for (int k = 0; k < 400; ++k) {
            // Both above or both below (the opaque models are two-sided; the dielectric's reflection too).
            const float side = k % 2 ? 1.0f : -1.0f;
            const Vec3 a = direction_at(side * (0.02 + 0.98 * rng.uniform()), 2.0 * std::numbers::pi * rng.uniform());
            Vec3 b = direction_at(side * (0.02 + 0.98 * rng.uniform()), 2.0 * std::numbers::pi * rng.uniform());
            // Every other pair near the mirror direction, where the narrowest lobes are non-zero.
            if (k % 4 < 2) b = glm::normalize(Vec3(-a.x, -a.y, a.z) + 2e-3f * (b - Vec3(0.0f, 0.0f, b.z)));
            for (TransportMode mode : {TransportMode::radiance, TransportMode::importance}) {
                const RGB fab = m.material->eval(t, a, b, mode), fba = m.material->eval(t, b, a, mode);
                for (int ch = 0; ch < 3; ++ch) {
                    if (fab[ch] < 1e-12f && fba[ch] < 1e-12f) continue;
                    ++compared;
                    INFO(m.label << " pair " << k << " channel " << ch << ": " << fab[ch] << " vs " << fba[ch]);
                    CHECK(rel_diff(fab[ch], fba[ch]) < 1e-3);
                }
            }
        }
        INFO(m.label);
        CHECK(compared > 0);
    }
}

TEST_CASE("rough transmission obeys the generalised reciprocity and its adjoint", "[shading][sampling]") {
    Rng rng(0xd1e1ULL, 3);
    for (double r : {0.05, 0.3, 0.9}) {
        for (const char* ior_outside : {"1", "1.5"}) {
            const bool inverted = std::string(ior_outside) == "1.5";  // a bubble: the dense side is outside
            const auto m = make_material(
                "rough-dielectric",
                Params().set("roughness", r).set("ior", inverted ? 1.0 : 1.5).set("ior_outside", inverted ? 1.5 : 1.0));
            const SurfaceTerms t = m->terms(TextureLookup{});
            const float n_above = inverted ? 1.5f : 1.0f, n_below = inverted ? 1.0f : 1.5f;
            int compared = 0;
            for (int k = 0; k < 2000; ++k) {
                const Vec3 o = direction_at(0.02 + 0.98 * rng.uniform(), 2.0 * std::numbers::pi * rng.uniform());
                const Vec3 i = direction_at(-(0.02 + 0.98 * rng.uniform()), 2.0 * std::numbers::pi * rng.uniform());
                const float f_oi = m->eval(t, o, i, TransportMode::radiance).g;
                const float f_io = m->eval(t, i, o, TransportMode::radiance).g;
                const float f_oi_adjoint = m->eval(t, o, i, TransportMode::importance).g;
                if (f_oi < 1e-6f && f_io < 1e-6f) continue;
                ++compared;
                INFO("roughness " << r << " ior_outside " << ior_outside << " pair " << k);
                // f(wi -> wo) / n_o^2 = f(wo -> wi) / n_i^2, with wo = o above and wi = i below.
                CHECK(rel_diff(f_oi / (n_above * n_above), f_io / (n_below * n_below)) < 1e-3);
                CHECK(rel_diff(f_oi_adjoint, f_io) < 1e-3);
            }
            CHECK(compared > 100);
        }
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
