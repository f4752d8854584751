// The delta lobes (mirror, smooth glass, kr/kt of any material, opacity's pass-through): how often each is
// chosen, by an exact binomial test against the Fresnel reflectance (or the weights), Sidak-corrected.
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/shading/optics.hpp>
#include <rtlab/shading_testing/statistics.hpp>

#include <catch2/catch.hpp>

#include "sampled_material_cases.hpp"

#include <optional>
#include <string>

using namespace rtlab;
using namespace rtlab::test;
using namespace rtlab::shading_testing;

namespace {

struct DeltaCase {
    std::string label;
    std::shared_ptr<const Material> material;
    float cos_o;
    double expected;    // probability of the counted outcome
    LobeFlags counted;  // the flags a counted draw has
};

std::vector<DeltaCase> delta_cases() {
    std::vector<DeltaCase> cases;
    const auto glass = make_material("glass", {});
    const auto water = make_material("glass", Params().set("ior", 1.33));
    const auto shell = make_material("glass", Params().set("ior", 1.0).set("ior_outside", 1.5));  // air inside glass
    const auto add_glass = [&](const std::string& label, const std::shared_ptr<const Material>& m, float n_in,
                               float n_out, float c) {
        const float eta = c > 0.0f ? n_out / n_in : n_in / n_out;  // n_incident / n_transmitted
        cases.push_back({label, m, c, fresnel_dielectric(std::abs(c), eta), kLobeSpecular | kLobeReflection});
    };
    for (float c : {1.0f, 0.7f, 0.3f, 0.05f, -0.95f, -0.8f, -0.7f, -0.05f}) add_glass("glass", glass, 1.5f, 1.0f, c);
    for (float c : {0.5f, 0.05f, -0.9f, -0.5f}) add_glass("water", water, 1.33f, 1.0f, c);
    for (float c : {0.9f, 0.6f, -0.5f}) add_glass("air bubble in glass", shell, 1.0f, 1.5f, c);
    // A cut-out lets 1 - opacity through; the rest is Lambert.
    const auto leaf = make_material("lambert", Params().set("albedo", 0.5).set("opacity", 0.6));
    for (float c : {0.8f, -0.3f}) cases.push_back({"cut-out", leaf, c, 0.4, kLobeSpecular | kLobeTransmission});
    // kr and kt without Fresnel, on a Lambert base: chances 0.2, 0.3 and 0.5 (= 1 - kr - kt).
    const auto coated = make_material("lambert", Params().set("albedo", 0.5).set("kr", 0.2).set("kt", 0.3));
    cases.push_back({"kr on lambert", coated, 0.6f, 0.2, kLobeSpecular | kLobeReflection});
    cases.push_back({"kt on lambert", coated, 0.6f, 0.3, kLobeSpecular | kLobeTransmission});
    return cases;
}

}  // namespace

TEST_CASE("delta lobes are chosen as often as Fresnel and the weights say", "[shading][sampling]") {
    const std::vector<DeltaCase> cases = delta_cases();
    const double level = sidak_level(0.01, static_cast<int>(cases.size()));
    const int n = 20000 / kSampleScale;
    std::uint64_t stream = 0;
    for (const DeltaCase& d : cases) {
        const SurfaceTerms t = d.material->terms(TextureLookup{});
        const Vec3 wo = incident(d.cos_o);
        Rng rng(0xde17aULL, ++stream);
        int counted = 0, off_weight = 0;
        for (int k = 0; k < n; ++k) {
            const float uc = rng.uniform();
            const std::optional<BsdfSample> s =
                d.material->sample(t, wo, uc, rng.uniform2(), TransportMode::importance);
            if (s && s->flags == d.counted) ++counted;
            // Importance mode, lobes chosen in proportion to their weights: every delta draw carries exactly 1.
            if (s && (s->flags & kLobeSpecular) && std::abs(s->value.g - 1.0f) > 1e-5f) ++off_weight;
        }
        CHECK(off_weight == 0);
        const double p = binomial_p_value(counted, n, d.expected);
        INFO(d.label << " cos_o " << d.cos_o << ": " << counted << " of " << n << ", expected fraction " << d.expected
                     << ", p " << p << " (level " << level << ")");
        CHECK(p > level);
    }
}

TEST_CASE("the mirror reflects along the mirror direction with kr weighted by Fresnel", "[shading][sampling]") {
    const auto plain = make_material("mirror", Params().set("kr", 0.8));
    const auto dielectric = make_material("mirror", Params().set("fresnel", true).set("ior", 1.5));
    for (float c : {1.0f, 0.5f, 0.05f, -0.5f}) {
        const Vec3 wo = incident(c);
        for (const auto& m : {plain, dielectric}) {
            const SurfaceTerms t = m->terms(TextureLookup{});
            const auto s = m->sample(t, wo, 0.5f, Vec2(0.5f), TransportMode::radiance);
            REQUIRE(s);
            INFO("cos_o " << c);
            CHECK(s->flags == (kLobeSpecular | kLobeReflection));
            CHECK(s->wi.x == -wo.x);
            CHECK(s->wi.y == -wo.y);
            CHECK(s->wi.z == wo.z);
            const float expected = m == plain ? 0.8f : fresnel_dielectric(std::abs(c), c > 0.0f ? 1.0f / 1.5f : 1.5f);
            CHECK(s->value.g * s->pdf == Approx(expected).epsilon(1e-5));
            CHECK(m->eval(t, wo, s->wi, TransportMode::radiance).is_black());
            CHECK(m->pdf(t, wo, s->wi, TransportMode::radiance) == 0.0f);
        }
    }
}
