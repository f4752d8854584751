// The checks of a sampled material: chi-square, consistency of sample() with eval() and pdf(), albedo and
// reciprocity, and check_material, which runs them all.
#include <rtlab/shading_testing/bsdf_check.hpp>
#include <rtlab/shading_testing/sphere_quadrature.hpp>
#include <rtlab/shading_testing/statistics.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace rtlab::shading_testing {

namespace {

double rel_diff(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-30}); }

float largest_channel(const RGB& c) { return std::max({c.r, c.g, c.b}); }

/// The index of refraction on the side of direction w.
float index_at(const Material& m, const Vec3& w) { return w.z > 0.0f ? m.ior_outside() : m.ior_inside(); }

/// w refracted straight through the material's interface (nullopt beyond the critical angle).
std::optional<Vec3> refracted(const Material& m, const Vec3& w) {
    const float eta = index_at(m, w) / index_at(m, -w);
    const float cos2_t = 1.0f - eta * eta * (1.0f - w.z * w.z);
    if (!(cos2_t > 0.0f)) return std::nullopt;
    return glm::normalize(Vec3(-eta * w.x, -eta * w.y, w.z > 0.0f ? -std::sqrt(cos2_t) : std::sqrt(cos2_t)));
}

std::string vec(const Vec3& v) {
    std::ostringstream s;
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

}  // namespace

Vec3 incident_direction(float c, float azimuth) { return direction_at(c, azimuth); }

std::vector<Vec3> lobe_hints(const Material& material, const SurfaceTerms& terms, const Vec3& wo) {
    std::vector<Vec3> hints{Vec3(-wo.x, -wo.y, wo.z)};
    // The refracted direction only where the material's own lobes reach it: refining around it costs as much
    // as around the mirror direction, for nothing when the material is opaque.
    if (const std::optional<Vec3> t = refracted(material, wo);
        t && (material.pdf(terms, wo, *t, TransportMode::radiance) > 0.0f ||
              !material.eval(terms, wo, *t, TransportMode::radiance).is_black()))
        hints.push_back(*t);
    return hints;
}

ChiSquareResult chi_square_directions(const Material& material, const SurfaceTerms& terms, const Vec3& wo,
                                      TransportMode mode, Rng& rng, int samples, const std::vector<Vec3>& extra_hints,
                                      ChiSquareSettings settings) {
    const auto sample = [&](Rng& r) -> std::optional<Vec3> {
        const float uc = r.uniform();
        const Vec2 u = r.uniform2();
        const std::optional<BsdfSample> s = material.sample(terms, wo, uc, u, mode);
        if (!s || (s->flags & kLobeSpecular)) return std::nullopt;
        return s->wi;
    };
    const auto pdf = [&](const Vec3& wi) { return static_cast<double>(material.pdf(terms, wo, wi, mode)); };
    std::vector<Vec3> hints = lobe_hints(material, terms, wo);
    hints.insert(hints.end(), extra_hints.begin(), extra_hints.end());
    return chi_square_test(sample, pdf, hints, rng, samples, settings);
}

ConsistencyResult sample_consistency(const Material& material, const SurfaceTerms& terms, const Vec3& wo,
                                     TransportMode mode, Rng& rng, int samples, double tolerance) {
    ConsistencyResult r;
    for (int k = 0; k < samples; ++k) {
        const float uc = rng.uniform();
        const Vec2 u = rng.uniform2();
        const std::optional<BsdfSample> s = material.sample(terms, wo, uc, u, mode);
        if (!s || (s->flags & kLobeSpecular)) continue;
        ++r.checked;
        const float pdf = material.pdf(terms, wo, s->wi, mode);
        const RGB f = material.eval(terms, wo, s->wi, mode);
        const bool bad_pdf = rel_diff(pdf, s->pdf) > tolerance;
        bool bad_value = false;
        for (int ch = 0; ch < 3; ++ch)
            bad_value = bad_value || rel_diff(f[ch] * std::abs(s->wi.z) / pdf, s->value[ch]) > tolerance;
        r.bad_pdf += bad_pdf;
        r.bad_value += bad_value;
        if ((bad_pdf || bad_value) && r.first_bad.empty()) {
            std::ostringstream m;
            m << "wi " << vec(s->wi) << ": sample() pdf " << s->pdf << " value " << s->value.g << ", pdf() " << pdf
              << ", eval() |cos| / pdf " << f.g * std::abs(s->wi.z) / pdf << " (green)";
            r.first_bad = m.str();
        }
    }
    return r;
}

double directional_albedo(const Material& material, const SurfaceTerms& terms, const Vec3& wo, TransportMode mode,
                          const std::vector<Vec3>& extra_hints, double tolerance) {
    const auto f = [&](const Vec3& wi) {
        return double(largest_channel(material.eval(terms, wo, wi, mode))) * std::abs(wi.z);
    };
    std::vector<Vec3> hints = lobe_hints(material, terms, wo);
    hints.insert(hints.end(), extra_hints.begin(), extra_hints.end());
    double total = SphereQuadrature(f, hints, tolerance).integrate_sphere(12, 12);
    constexpr int kGrid = 100000;
    for (int i = 0; i < kGrid; ++i) {
        const std::optional<BsdfSample> s = material.sample(terms, wo, (i + 0.5f) / kGrid, Vec2(0.5f), mode);
        if (s && (s->flags & kLobeSpecular)) total += double(largest_channel(s->value)) / kGrid;
    }
    return total;
}

ReciprocityResult reciprocity(const Material& material, const SurfaceTerms& terms, Rng& rng, int pairs,
                              double tolerance) {
    ReciprocityResult r;
    const auto random_direction = [&](float side) {
        return direction_at(side * (0.02 + 0.98 * rng.uniform()), 2.0 * std::numbers::pi * rng.uniform());
    };
    // Within 2e-3 radians of `axis`: where the narrowest lobes (roughness 0.01, exponents 5000) are non-zero.
    const auto near = [&](const Vec3& axis) {
        const Vec3 jitter = random_direction(1.0f);
        return glm::normalize(axis + 2e-3f * Vec3(jitter.x, jitter.y, 0.0f));
    };
    for (int k = 0; k < pairs; ++k) {
        const bool across = k % 4 >= 2;  // a below b, or on the same side
        const Vec3 a = random_direction(k % 8 < 4 ? 1.0f : -1.0f);
        Vec3 b = random_direction(across ? -std::copysign(1.0f, a.z) : std::copysign(1.0f, a.z));
        if (k % 2 == 1) {
            if (!across) {
                b = near(Vec3(-a.x, -a.y, a.z));
            } else if (const std::optional<Vec3> t = refracted(material, a)) {
                b = near(*t);
            }
        }
        const float n_a = index_at(material, a), n_b = index_at(material, b);
        const RGB ab = material.eval(terms, a, b, TransportMode::radiance) / (n_a * n_a);
        const RGB ba = material.eval(terms, b, a, TransportMode::radiance) / (n_b * n_b);
        const RGB ab_adjoint = material.eval(terms, a, b, TransportMode::importance);
        const RGB ba_radiance = material.eval(terms, b, a, TransportMode::radiance);
        for (int ch = 0; ch < 3; ++ch)
            for (const auto& [x, y, what] :
                 {std::tuple(ab[ch], ba[ch], "f(a, b) / n_a^2 against f(b, a) / n_b^2"),
                  std::tuple(ab_adjoint[ch], ba_radiance[ch], "importance f(a, b) against radiance f(b, a)")}) {
                if (!(x > 1e-6f || y > 1e-6f)) continue;
                ++r.compared;
                if (rel_diff(x, y) <= tolerance) continue;
                ++r.failed;
                if (r.first_bad.empty()) {
                    std::ostringstream m;
                    m << "a " << vec(a) << " b " << vec(b) << " channel " << ch << ": " << what << ": " << x
                      << " against " << y;
                    r.first_bad = m.str();
                }
            }
    }
    return r;
}

BsdfCheckReport check_material(const Material& material, const SurfaceTerms& terms, const BsdfCheckOptions& o) {
    BsdfCheckReport report;
    std::ostringstream failures;
    const auto fail = [&](const std::string& what) {
        report.passed = false;
        failures << what << "\n";
    };
    const int own_tests = static_cast<int>(o.cosines.size());
    report.level = sidak_level(o.significance, std::max(o.family_size, own_tests));
    std::uint64_t stream = 0;
    for (float c : o.cosines) {
        const Vec3 wo = incident_direction(c, o.azimuth);
        const std::vector<Vec3> extra = o.extra_hints ? o.extra_hints(wo) : std::vector<Vec3>{};
        std::ostringstream at;
        at << "cos_o " << c << ": ";

        Rng rng(o.seed, ++stream);
        const ChiSquareResult chi2 = chi_square_directions(material, terms, wo, TransportMode::radiance, rng,
                                                           o.chi_square_samples, extra, o.chi_square);
        ++report.chi_square_tests;
        report.smallest_p = std::min(report.smallest_p, chi2.p_value);
        if (!chi2.failure.empty()) {
            fail(at.str() + "sample() draws where pdf() is 0: " + chi2.failure);
        } else if (!(chi2.p_value > report.level)) {
            std::ostringstream m;
            m << at.str() << "sampled directions do not follow pdf(): chi2 " << chi2.statistic << " dof " << chi2.dof
              << " p " << chi2.p_value << " < level " << report.level << "; worst " << chi2.worst;
            fail(m.str());
        }
        if (chi2.pdf_integral > 1.0 + 1e-4) {
            std::ostringstream m;
            m << at.str() << "pdf() integrates to " << chi2.pdf_integral << " > 1";
            fail(m.str());
        }

        for (TransportMode mode : {TransportMode::radiance, TransportMode::importance}) {
            Rng r(o.seed ^ 0xc0ffeeULL, ++stream);
            const ConsistencyResult cr = sample_consistency(material, terms, wo, mode, r, o.consistency_samples);
            const char* name = mode == TransportMode::radiance ? "radiance" : "importance";
            if (cr.checked == 0) {
                // A material with no sampled lobes (only delta lobes, or none) has nothing to compare.
                if (material.pdf(terms, wo, Vec3(0.0f, 0.0f, wo.z > 0.0f ? 1.0f : -1.0f), mode) > 0.0f)
                    fail(at.str() + name + ": sample() drew no direction where pdf() is non-zero");
            } else if (!cr.passed()) {
                std::ostringstream m;
                m << at.str() << name << ": sample() disagrees with eval() and pdf() on " << cr.bad_value
                  << " values and " << cr.bad_pdf << " pdfs of " << cr.checked << "; first " << cr.first_bad;
                fail(m.str());
            }
        }

        const double albedo = directional_albedo(material, terms, wo, TransportMode::importance, extra);
        report.largest_albedo = std::max(report.largest_albedo, albedo);
        if (o.expected_albedo ? std::abs(albedo - *o.expected_albedo) > 1e-3 : albedo > 1.0 + 2e-3) {
            std::ostringstream m;
            m << at.str() << "albedo " << albedo << (o.expected_albedo ? ", expected " : ", more than ")
              << (o.expected_albedo ? *o.expected_albedo : 1.0);
            fail(m.str());
        }
    }
    std::ostringstream summary;
    summary << report.chi_square_tests << " chi-square tests, smallest p " << report.smallest_p << " (level "
            << report.level << "); largest albedo " << report.largest_albedo;
    if (o.reciprocity_pairs > 0) {
        Rng rng(o.seed ^ 0xbeefULL, ++stream);
        const ReciprocityResult rr = reciprocity(material, terms, rng, o.reciprocity_pairs);
        summary << "; reciprocity " << rr.compared - rr.failed << " of " << rr.compared << " comparisons";
        if (rr.compared == 0) fail("reciprocity: every pair evaluated to 0");
        if (rr.failed > 0) fail("not reciprocal: " + rr.first_bad);
    }
    report.message = failures.str() + summary.str();
    return report;
}

}  // namespace rtlab::shading_testing
