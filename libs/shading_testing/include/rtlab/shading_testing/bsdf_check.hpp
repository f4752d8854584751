#pragma once
/// \brief Checks of a sampled material (Material::eval, pdf and sample of rtlab/shading/material.hpp) that a test
/// of any material can run, a plugin's included: the chi-square fit of its sampled directions to its pdf, the
/// pdf's normalisation, sample() against eval() and pdf(), the directional albedo, and reciprocity. Each returns
/// its numbers and a message; none depends on a test framework. docs/sampled-materials.md shows them in use.
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/shading_testing/chi_square.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::shading_testing {

/// The unit direction with cosine c to the normal at the given azimuth (off the axes by default, so that an
/// anisotropic model is not seen only along its tangent).
Vec3 incident_direction(float c, float azimuth = 0.3f);

/// Where the narrow lobes of `material` peak for wo: the mirror direction, and the straight refraction through
/// its Whitted interface (ior_outside above, ior_inside below) when its lobes reach there. The quadratures refine
/// their mesh around these, so that a lobe narrower than their first nodes' spacing is found.
std::vector<Vec3> lobe_hints(const Material& material, const SurfaceTerms& terms, const Vec3& wo);

/// Chi-square of sample()'s directions for wo against pdf(), over `samples` draws from rng: delta-lobe draws and
/// lost ones fill the outside bin, expected samples (1 - integral of pdf). extra_hints add to lobe_hints().
ChiSquareResult chi_square_directions(const Material& material, const SurfaceTerms& terms, const Vec3& wo,
                                      TransportMode mode, Rng& rng, int samples,
                                      const std::vector<Vec3>& extra_hints = {}, ChiSquareSettings settings = {});

/// How sample() agrees with eval() and pdf(): for each non-delta draw, its pdf against pdf(wo, wi) and its value
/// against eval(wo, wi) |cos(theta_i)| / pdf, each channel to `tolerance` relative.
struct ConsistencyResult {
    int checked = 0, bad_pdf = 0, bad_value = 0;
    std::string first_bad;  ///< the first draw that disagreed, with both sides' numbers
    bool passed() const { return checked > 0 && bad_pdf == 0 && bad_value == 0; }
};
ConsistencyResult sample_consistency(const Material& material, const SurfaceTerms& terms, const Vec3& wo,
                                     TransportMode mode, Rng& rng, int samples, double tolerance = 1e-3);

/// The directional albedo for wo: the integral of eval(wo, wi) |cos(theta_i)| over the sphere (adaptive
/// quadrature refined around lobe_hints and extra_hints, to `tolerance` in each of its 144 starting cells) plus
/// the delta lobes' weights (sample() swept over a fine grid of uc: a delta lobe's value times its share of the
/// grid is its weight). Of the largest channel at each direction: an upper bound of every channel's albedo, and
/// each channel's own for a grey material. In importance mode it is the fraction of the light arriving from wo
/// that leaves (at most 1 for a model that creates no energy); in radiance mode transmission adds the
/// (n_wo / n_wi)^2 squeeze of solid angle.
double directional_albedo(const Material& material, const SurfaceTerms& terms, const Vec3& wo, TransportMode mode,
                          const std::vector<Vec3>& extra_hints = {}, double tolerance = 1e-6);

/// Reciprocity, generalised to transmission: for pairs of directions a, b on the same side and on opposite
/// sides (random, and near the mirror or refracted direction, where narrow lobes are non-zero), in radiance mode
/// eval(a, b) / n_a^2 = eval(b, a) / n_b^2 (n the index on each direction's side: ior_outside above, ior_inside
/// below; plain reciprocity on one side), and eval(a, b) in importance mode = eval(b, a) in radiance mode, each
/// channel to `tolerance` relative where either side exceeds 1e-6. Holds for a reciprocal model under Whitted
/// weights that do not depend on wo (no fresnel-weighted kr or kt next to its own lobes).
struct ReciprocityResult {
    int compared = 0, failed = 0;
    std::string first_bad;
    bool passed() const { return compared > 0 && failed == 0; }
};
ReciprocityResult reciprocity(const Material& material, const SurfaceTerms& terms, Rng& rng, int pairs,
                              double tolerance = 1e-3);

/// What check_material runs: the defaults are those the built-in materials pass in rtlab's own tests.
struct BsdfCheckOptions {
    /// Incident cosines: normal to grazing (<= 0.05) above and one from below (opaque models are two-sided).
    std::vector<float> cosines{1.0f, 0.8f, 0.5f, 0.2f, 0.04f, -0.6f};
    float azimuth = 0.3f;
    int chi_square_samples = 100000;  ///< per incident direction
    ChiSquareSettings chi_square;
    int consistency_samples = 2000;  ///< per incident direction and mode
    int reciprocity_pairs = 400;     ///< 0 for a model that is not reciprocal
    /// The chance that a correct material fails a chi-square test, for the whole family (Sidak-corrected per test).
    double significance = 0.01;
    /// Chi-square tests in the family: 0 = the ones this call runs; a test that checks several materials passes
    /// the total, so that their union keeps `significance`.
    int family_size = 0;
    /// Checked to 1e-3 when set (1 for a lossless material), else only albedo <= 1 (+ 2e-3 for the quadrature).
    std::optional<double> expected_albedo;
    std::uint64_t seed = 0x5eedf00dULL;  ///< fixed: the outcome is the same on every run
    /// More directions where the material's lobes peak for wo, beyond lobe_hints().
    std::function<std::vector<Vec3>(const Vec3& wo)> extra_hints;
};

/// \brief The outcome of check_material: passed, and a message with every failure (or, when it passed, a
/// summary of the numbers) to print.
struct BsdfCheckReport {
    bool passed = true;
    std::string message;
    int chi_square_tests = 0;
    double level = 0.0;           ///< the per-test significance level of the chi-square tests
    double smallest_p = 1.0;      ///< of the chi-square tests
    double largest_albedo = 0.0;  ///< importance mode, over the incident directions
};

/// Runs every check above for each incident cosine of the options: chi-square (radiance mode) with the pdf's
/// integral at most 1, sample() against eval() and pdf() in both modes, the albedo in importance mode, and
/// reciprocity once.
BsdfCheckReport check_material(const Material& material, const SurfaceTerms& terms,
                               const BsdfCheckOptions& options = {});

}  // namespace rtlab::shading_testing
