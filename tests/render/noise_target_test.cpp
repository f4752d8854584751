#include "image_plane.hpp"
#include "noisy_sphere.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/render/noise_target.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdio>

using namespace rtlab;
using namespace rtlab::test;

namespace {

/// A radiance source whose pixel means are known exactly, with an edge inside every pixel and noise that differs
/// across the image: channel c's value = colour_c(x, y) * g(u) * h_c, u the offset across the pixel, g(u) = 1 below
/// the pixel's edge position e and 0.25 above it, h_c = 2 / s^2 when w1 + w2 < s (w1, w2 two of the integrator's
/// dimensions, from different pairs, other ones for each channel) else 0: mean exactly 1, per-sample relative
/// variance 2 / s^2 - 1. The left third of the image has s = 0.4 (relative variance 11.5), the rest s = 1 (1).
class KnownMeans final : public RadianceSource {
public:
    explicit KnownMeans(int width) : m_width(width) {}
    RGB radiance(const Ray& r, const SampleKey& key, RayCounters& counters) const override {
        return sample_radiance(CameraSample{r, SampleStream(SampleSequence::independent, key)}, counters);
    }
    RGB sample_radiance(const CameraSample& sample, RayCounters&) const override {
        const int x = static_cast<int>(std::floor(sample.ray.origin.x));
        const int y = static_cast<int>(std::floor(sample.ray.origin.y));
        const float u = sample.ray.origin.x - static_cast<float>(x);
        const float g = u < edge(x, y) ? 1.0f : 0.25f;
        const float s = spread(x);
        float f[3];
        for (std::uint32_t c = 0; c < 3; ++c) {
            const float w1 = sample.stream.get2d(kFirstIntegratorPair + c).x;
            const float w2 = sample.stream.get2d(kFirstIntegratorPair + 3 + c).x;
            f[c] = w1 + w2 < s ? 2.0f / (s * s) : 0.0f;
        }
        return colour(x, y) * g * RGB(f[0], f[1], f[2]);
    }
    /// The exact pixel means (the edge position is a float: the mean uses it as the sampler compares with it).
    Image means(int w, int h) const {
        Image out(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double e = edge(x, y);
                out.at(x, y) = colour(x, y) * static_cast<float>(e + 0.25 * (1.0 - e));
            }
        return out;
    }

private:
    static float edge(int x, int y) { return 0.2f + 0.6f * static_cast<float>((x * 7 + y * 3) % 11) / 10.0f; }
    static RGB colour(int x, int y) {
        const float c = 0.05f + 0.9f * static_cast<float>((x * 5 + y * 11) % 13) / 12.0f;
        return RGB(c, 0.5f * c + 0.2f, 1.0f - 0.5f * c);
    }
    float spread(int x) const { return x < m_width / 3 ? 0.4f : 1.0f; }
    int m_width;
};

ProgressiveSettings halves(int cap, std::uint64_t seed, int threads = 1) {
    ProgressiveSettings s;
    s.sequence = SampleSequence::sobol_halves;
    s.spp = cap;
    s.seed = seed;
    s.threads = threads;
    s.tile_size = 8;
    return s;
}

}  // namespace

TEST_CASE("the half-image estimate is the pixel mean's error for independent halves of any sizes", "[noise]") {
    // One pixel, samples 1, 5 (even) and 2 (odd), channel values v, 0, 0: A = 3, B = 2, n = 3, a = 2, b = 1, so the
    // variance estimate is (A - B)^2 a b / n^2 = 2/9, and the term is (2/9) / (A B + eps) averaged with two zeros.
    SampleBuffer buffer(1, 1);
    buffer.add(0, 0, 0, RGB(1, 0, 0));
    buffer.add(0, 0, 1, RGB(2, 0, 0));
    buffer.add(0, 0, 2, RGB(5, 0, 0));
    const double expected = (2.0 / 9.0) / (3.0 * 2.0 + kRelMseEps) / 3.0;
    CHECK(pixel_error_estimate(buffer, 0, 0) == Approx(expected).epsilon(1e-12));
    SampleBuffer one(1, 1);
    one.add(0, 0, 0, RGB(1, 1, 1));
    CHECK(std::isinf(pixel_error_estimate(one, 0, 0)));  // no odd half yet

    // Many pixels of independent samples of a known distribution: the estimate's mean is the true squared error's,
    // for even and for odd counts. Uniform [0, 2) samples: mean 1, variance 1/3; n = 33: Var I = 1/99.
    const int w = 400, h = 100;
    for (const std::uint32_t n : {32u, 33u}) {
        SampleBuffer b(w, h);
        Rng rng(42 + n);
        double true_error = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                for (std::uint32_t i = 0; i < n; ++i)
                    b.add(x, y, i, RGB(2.0f * rng.uniform(), 2.0f * rng.uniform(), 2.0f * rng.uniform()));
                for (int c = 0; c < 3; ++c) {
                    const double d = b.mean(x, y)[c] - 1.0;
                    true_error += d * d / (1.0 + kRelMseEps) / 3.0;
                }
            }
        true_error /= w * h;
        const double expected_error = (1.0 / 3.0) / n / (1.0 + kRelMseEps);
        // 120,000 terms of relative sd about sqrt(2): the mean's relative sd is 0.4%. A B in the denominator makes
        // the estimate high by about 6 Var I / mu^2 (6%; noise_target.cpp says why), never low.
        const double estimate = error_estimate(b);
        INFO("n " << n << " estimate " << estimate << " true " << true_error << " expected " << expected_error);
        CHECK(true_error == Approx(expected_error).epsilon(0.03));
        CHECK(estimate > 0.98 * expected_error);
        CHECK(estimate < (1.0 + 8.0 * expected_error) * expected_error);
    }
}

TEST_CASE("relative MSE is the mean over pixels and channels with eps 0.01", "[noise]") {
    Image a(2, 1), r(2, 1);
    r.at(0, 0) = RGB(1, 0, 0);
    a.at(0, 0) = RGB(1.5f, 0, 0);
    a.at(1, 0) = RGB(0, 0.1f, 0);
    const double expected = (0.25 / 1.01 + 0.01 / 0.01) / 6.0;
    CHECK(relative_mse(a, r) == Approx(expected));
    CHECK_THROWS_AS(relative_mse(a, Image(1, 1)), Error);
}

TEST_CASE("the half-image estimate follows the error under sobol_halves and overstates it under sobol", "[noise]") {
    // Why a noise target renders with sobol_halves: sobol's even and odd samples are complementary halves of one
    // stratified point set, negatively correlated, so (A - B)^2 measures something like the independent samples'
    // error rather than the stratified one. A smooth function of the pixel offset, 16 samples, 4000 pixels.
    auto ratio = [](SampleSequence sequence) {
        double estimate = 0.0, truth = 0.0;
        for (std::uint32_t p = 0; p < 4000; ++p) {
            SampleBuffer b(1, 1);
            for (std::uint32_t i = 0; i < 16; ++i) {
                const Vec2 u = SampleStream(sequence, {3, p, 7, i, 0}).get2d(kPixelPair);
                b.add(0, 0, i, RGB(u.x + u.y * u.y));
            }
            const double d = b.mean(0, 0).r - (0.5 + 1.0 / 3.0);
            truth += d * d / ((0.5 + 1.0 / 3.0) * (0.5 + 1.0 / 3.0) + kRelMseEps);
            estimate += pixel_error_estimate(b, 0, 0);
        }
        return estimate / truth;
    };
    const double halves = ratio(SampleSequence::sobol_halves), sobol = ratio(SampleSequence::sobol);
    INFO("estimate / true error: sobol_halves " << halves << ", sobol " << sobol);
    CHECK(halves > 0.85);
    CHECK(halves < 1.2);
    CHECK(sobol > 4.0);
    // The even samples of sobol_halves are the sobol sequence's points: sample 2j is point j.
    for (std::uint32_t j = 0; j < 16; ++j) {
        const Vec2 even = SampleStream(SampleSequence::sobol_halves, {9, 1, 2, 2 * j, 0}).get2d(kPixelPair);
        CHECK(even == SampleStream(SampleSequence::sobol, {9, 1, 2, j, 0}).get2d(kPixelPair));
    }
}

TEST_CASE("a noise target stops at the asked error and the true error is at most 1.1 times it", "[noise]") {
    // Known exact means, so the true error needs no reference. Three seeds, adaptive and uniform; every run must hold
    // the bound (deterministic: fixed seeds), and adaptive sampling must need fewer samples each time. Over 20 seeds
    // the true error at the stop was 0.51 to 0.66 times the target uniform and 0.55 to 0.72 adaptive (the estimate
    // errs on the safe side on these sparse samples: noise_target.cpp says why), the adaptive renders taking 32%
    // fewer samples.
    const int w = 48, h = 32;
    const KnownMeans source(w);
    const Image exact = source.means(w, h);
    const ImagePlaneCamera camera(w, h);
    const double target = 0.05;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        std::uint64_t samples[2] = {};
        for (const bool adaptive : {false, true}) {
            TargetSettings t;
            t.noise = target;
            t.adaptive = adaptive;
            const TargetResult r = render_to_target(camera, source, halves(1 << 14, seed), t);
            const double true_error = relative_mse(r.image, exact);
            samples[adaptive] = r.buffer.total_samples();
            INFO("seed " << seed << (adaptive ? " adaptive" : " uniform") << ": estimate " << r.estimate << " true "
                         << true_error << " samples " << samples[adaptive] << " passes " << r.passes);
            CHECK(r.stop == TargetStop::noise);
            CHECK(r.estimate <= target);
            CHECK(true_error <= 1.1 * target);
            CHECK(same_bytes(r.image, r.buffer.mean_image()));
        }
        CHECK(samples[1] < 0.8 * samples[0]);
    }
}

TEST_CASE("adaptive passes give the same bytes for 1 and 2 threads and any tile size", "[noise]") {
    const KnownMeans source(20);
    const ImagePlaneCamera camera(20, 12);
    TargetSettings t;
    t.noise = 0.03;
    ProgressiveSettings one = halves(1 << 12, 7, 1), two = halves(1 << 12, 7, 2);
    two.tile_size = 5;
    const TargetResult a = render_to_target(camera, source, one, t);
    const TargetResult b = render_to_target(camera, source, two, t);
    CHECK(a.buffer == b.buffer);
    CHECK(same_bytes(a.image, b.image));
    CHECK(a.passes == b.passes);
    // Adaptive: the noisy left third got more samples than the rest.
    double left = 0.0, right = 0.0;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 20; ++x) (x < 6 ? left : right) += a.buffer.count(x, y);
    INFO("samples per pixel: left " << left / 72 << ", right " << right / 168);
    CHECK(left / 72 > 1.5 * right / 168);
}

TEST_CASE("a render to a target stops at the cap or the time budget and refuses bad settings", "[noise]") {
    const KnownMeans source(9);
    const ImagePlaneCamera camera(9, 6);
    TargetSettings t;
    t.noise = 1e-6;  // never reached under the cap
    const TargetResult capped = render_to_target(camera, source, halves(40, 3), t);
    CHECK(capped.stop == TargetStop::samples);
    CHECK(capped.buffer.min_count() == 40);
    CHECK(capped.buffer.counts() == std::vector<std::uint32_t>(54, 40));

    // A time budget far below one pass: the first pass still completes, so no pixel is left black. Nothing here
    // depends on how fast the machine is.
    TargetSettings quick;
    quick.seconds = 1e-9;
    const TargetResult timed = render_to_target(camera, source, halves(1 << 16, 3), quick);
    CHECK(timed.stop == TargetStop::time);
    CHECK(timed.buffer.min_count() >= 1);
    CHECK_FALSE(timed.stats.cancelled);

    std::atomic<bool> stop{true};
    ProgressiveCallbacks cb;
    cb.stop = &stop;
    const TargetResult stopped = render_to_target(camera, source, halves(64, 3), t, cb);
    CHECK(stopped.stop == TargetStop::interrupted);
    CHECK(stopped.stats.cancelled);

    ProgressiveSettings sobol = halves(64, 3);
    sobol.sequence = SampleSequence::sobol;
    CHECK_THROWS_WITH(render_to_target(camera, source, sobol, t), Catch::Contains("not independent"));
    CHECK_THROWS_WITH(render_to_target(camera, source, halves(64, 3), TargetSettings{}),
                      Catch::Contains("noise target or a time budget"));
    ProgressiveRenderer renderer(camera, source, halves(8, 3));
    CHECK_THROWS_WITH(renderer.render_to(std::vector<std::uint32_t>(53, 4)), Catch::Contains("53 sample ends for 54"));
    CHECK(renderer.render_to(std::vector<std::uint32_t>(54, 0)));  // nothing to do is fine
    CHECK(renderer.buffer().total_samples() == 0);
    CHECK(supports_noise_target(IntegratorKind::path));
    CHECK(supports_noise_target(IntegratorKind::direct));
    CHECK(supports_noise_target(IntegratorKind::whitted));
}
