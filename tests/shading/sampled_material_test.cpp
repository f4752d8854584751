// Chi-square goodness of fit of every built-in material's sampled directions against its pdf, with the
// pdf's integral (1, or less where draws are lost below the horizon) checked on the way: the checks of
// rtlab::shading_testing (rtlab/shading_testing/bsdf_check.hpp), which a plugin's test runs the same way.
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/shading_testing/bsdf_check.hpp>
#include <rtlab/shading_testing/statistics.hpp>

#include <catch2/catch.hpp>

#include "sampled_material_cases.hpp"

#include <cstdlib>
#include <string>

using namespace rtlab;
using namespace rtlab::test;
using namespace rtlab::shading_testing;

namespace {

int chi_square_test_count() {
    int n = 0;
    for (const MaterialCase& m : glossy_cases())
        n += static_cast<int>((m.transmits ? dielectric_cosines() : opaque_cosines()).size());
    return n;
}

}  // namespace

TEST_CASE("every sampled material draws directions distributed as its pdf", "[shading][sampling]") {
    // Significance 1% for the whole family: Sidak-corrected per test. The seeds are fixed, so the outcome
    // is too; the correction keeps a change of seeds from failing by chance.
    const double level = sidak_level(0.01, chi_square_test_count());
    const int n = 100000 / kSampleScale;
    std::uint64_t stream = 0;
    for (const MaterialCase& m : glossy_cases()) {
        const SurfaceTerms t = m.material->terms(TextureLookup{});
        for (float c : m.transmits ? dielectric_cosines() : opaque_cosines()) {
            Rng rng(0x5eedf00dULL, ++stream);
            if (std::getenv("RTLAB_CHI2_ONLY") && m.label.find(std::getenv("RTLAB_CHI2_ONLY")) == std::string::npos)
                continue;
            const ChiSquareResult r =
                chi_square_directions(*m.material, t, incident(c), TransportMode::radiance, rng, n);
            INFO(m.label << " cos_o " << c << ": chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value
                         << " (level " << level << ") pdf integral " << r.pdf_integral << " outside "
                         << r.samples_outside << " " << r.failure << "; worst " << r.worst);
            CHECK(r.failure.empty());
            CHECK(r.p_value > level);
            CHECK(r.pdf_integral <= 1.0 + 1e-4);
            // Lambert loses nothing: its density is normalised.
            if (m.label == "lambert") CHECK(r.pdf_integral == Approx(1.0).margin(1e-4));
        }
    }
}
