#include <rtlab/core/error.hpp>
#include <rtlab/render/noise_target.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace rtlab {

double relative_mse(const Image& image, const Image& reference) {
    if (image.width() != reference.width() || image.height() != reference.height())
        throw Error("relative MSE: image " + std::to_string(image.width()) + "x" + std::to_string(image.height()) +
                    " and reference " + std::to_string(reference.width()) + "x" + std::to_string(reference.height()) +
                    " differ in size");
    double total = 0.0;
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = image.pixels()[i][c], r = reference.pixels()[i][c];
            total += (v - r) * (v - r) / (r * r + kRelMseEps);
        }
    return image.pixel_count() == 0 ? 0.0 : total / (3.0 * static_cast<double>(image.pixel_count()));
}

double pixel_error_estimate(const SampleBuffer& buffer, int x, int y) {
    // The pixel's image I is the mean of its n = a + b samples: a even ones with mean A, b odd ones with mean B, so
    // I = (a A + b B) / n. When the halves are independent and unbiased for the pixel's value mu, with per-sample
    // variance s^2 in both (the same sequence walked twice), Var A = s^2 / a and Var B = s^2 / b, so
    //   E[(A - B)^2] = Var A + Var B = s^2 (a + b) / (a b),  and  Var I = s^2 / n = E[(A - B)^2] a b / n^2.
    // With a = b = n / 2 the factor is 1/4: E[(A - B)^2] / 4 = Var((A + B) / 2), the full image's squared error.
    // The reference's square in the denominator is unknown. A B stands for it: E[A B] = E[A] E[B] = mu^2 for
    // independent halves. I^2 would not do: E[I^2] = mu^2 + Var I, and a path tracer's samples are skewed (rare bright
    // paths), so a bright sample raises I^2 with (A - B)^2 and the ratio hides it. On the Cornell box at 32x32
    // (8 seeds of sobol_halves, against a 16384-sample reference), the estimate over the true error was with I^2:
    // 0.37, 0.46, 0.65, 0.84, 1.10, 1.06 at 4, 8, 16, 32, 64, 128 samples; with A B: 1.10, 1.16, 1.39, 1.38, 1.30,
    // 1.11, on the safe side everywhere (A B falls as (A - B)^2 grows, which overstates noisy pixels a little).
    const PixelSums& p = buffer.at(x, y);
    const double a = p.count(0), b = p.count(1);
    if (a == 0.0 || b == 0.0) return std::numeric_limits<double>::infinity();
    const double n = a + b, factor = a * b / (n * n);
    double total = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double even = p.sum(0, c), odd = p.sum(1, c);
        const double d = even / a - odd / b;
        total += d * d * factor / (std::max(even / a * (odd / b), 0.0) + kRelMseEps);
    }
    return total / 3.0;
}

double error_estimate(const SampleBuffer& buffer) {
    double total = 0.0;
    for (int y = 0; y < buffer.height(); ++y)
        for (int x = 0; x < buffer.width(); ++x) total += pixel_error_estimate(buffer, x, y);
    const double pixels = static_cast<double>(buffer.width()) * static_cast<double>(buffer.height());
    return pixels > 0.0 ? total / pixels : 0.0;
}

bool supports_noise_target(IntegratorKind kind) {
    // No default: an integrator added to IntegratorKind must be decided on here (-Wswitch).
    switch (kind) {
        case IntegratorKind::whitted:
        case IntegratorKind::direct:
        case IntegratorKind::path:
            return true;
        case IntegratorKind::photon:
        case IntegratorKind::sppm:
            return false;
    }
    return false;
}

std::string target_stop_name(TargetStop stop) {
    switch (stop) {
        case TargetStop::noise:
            return "noise target reached";
        case TargetStop::samples:
            return "sample cap reached";
        case TargetStop::time:
            return "time budget spent";
        case TargetStop::interrupted:
            return "interrupted";
    }
    return "?";
}

namespace {

/// The most a pixel's count grows in one pass after the warm-up.
constexpr double kGrowth = 2.0;

void check_target(const ProgressiveSettings& s, const TargetSettings& t) {
    if (!(t.noise >= 0.0) || !(t.seconds >= 0.0) || !std::isfinite(t.noise) || !std::isfinite(t.seconds))
        throw Error("render to a target: noise and seconds must be finite and >= 0");
    if (t.noise == 0.0 && t.seconds == 0.0) throw Error("render to a target: give a noise target or a time budget");
    if (s.sequence == SampleSequence::sobol)
        throw Error(
            "render to a target: the sobol sequence's half-images are not independent (use sobol_halves or "
            "independent)");
    if (s.spp < 1 || static_cast<std::uint64_t>(s.first_sample) + static_cast<std::uint64_t>(s.spp) > 0xffffffffULL)
        throw Error("render to a target: the sample cap must be >= 1 and first sample + cap below 2^32, got " +
                    std::to_string(s.first_sample) + " + " + std::to_string(s.spp));
    if (t.min_samples < 2) throw Error("render to a target: min_samples must be at least 2 (one per half)");
}

/// Per-sample error of every pixel (its estimate times its count), and the same averaged over the pixel's 8
/// neighbours (fewer at the image's edges), leaving out its own: a pixel whose own estimate came out low by chance
/// would otherwise be given fewer samples and keep its low estimate, and the estimate at the stop would be low.
/// Measured, true error at the stop over the target, mean (largest), at targets 0.01 and 0.05: on the Cornell box at
/// 64x64 (10 seeds), with the 8 neighbours 0.86 (1.00) and 0.78 (1.01); with the 5x5 pixels around, the pixel's own
/// among them, 1.05 (1.10) and 0.96 (1.15), for 22% fewer samples but no smaller error times samples; with the
/// 5x5 pixels but not its own, 0.95 (1.08) and 0.77 (1.08). On the analytic test scene (48x32, 20 seeds), with
/// the 8 neighbours 0.92 (1.01) and 0.64 (0.72); with the pixel's own estimate as a floor, 1.07 (1.18) and 0.76
/// (0.82). The price of leaving the pixel out: a firefly raises its neighbours' counts, not its own (a ring in a
/// map of the counts); it is the evidence of rare bright paths there, not a pixel that is noisier than its ring.
struct PixelErrors {
    std::vector<double> per_sample, smoothed;
};

PixelErrors pixel_errors(const SampleBuffer& buffer) {
    const int w = buffer.width(), h = buffer.height();
    auto at = [w](int x, int y) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x; };
    PixelErrors e;
    e.per_sample.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    e.smoothed.resize(e.per_sample.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            e.per_sample[at(x, y)] = pixel_error_estimate(buffer, x, y) * static_cast<double>(buffer.count(x, y));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum = 0.0;
            int n = 0;
            for (int yy = std::max(0, y - 1); yy <= std::min(h - 1, y + 1); ++yy)
                for (int xx = std::max(0, x - 1); xx <= std::min(w - 1, x + 1); ++xx) {
                    if (xx == x && yy == y) continue;
                    sum += e.per_sample[at(xx, yy)];
                    ++n;
                }
            e.smoothed[at(x, y)] = sum / n;
        }
    return e;
}

/// The counts of the next adaptive pass: T_p = clamp(ceil(lambda sqrt(smoothed_p)), n_p, cap), the counts that reach
/// `goal` by the model (lambda the smallest, by bisection, whose predicted estimate, the mean of per_sample_p / T_p,
/// is at most `goal`; every pixel at the cap when even that does not reach it), then at most `growth` times n_p in
/// this pass, so that a pixel's count is decided from estimates of at least 1 / growth of its samples.
std::vector<std::uint32_t> adaptive_counts(const std::vector<std::uint32_t>& counts, const PixelErrors& e, double goal,
                                           std::uint32_t cap, double growth) {
    const std::size_t pixels = counts.size();
    auto target = [&](double lambda, std::size_t i) {
        const double n = counts[i];
        return std::max(n, std::min<double>(cap, std::ceil(lambda * std::sqrt(e.smoothed[i]))));
    };
    auto predicted = [&](double lambda) {
        double sum = 0.0;
        for (std::size_t i = 0; i < pixels; ++i) sum += e.per_sample[i] / target(lambda, i);
        return sum / static_cast<double>(pixels);
    };
    // Beyond lambda_max every pixel is at the cap.
    double lambda_max = 0.0;
    for (std::size_t i = 0; i < pixels; ++i)
        if (e.smoothed[i] > 0.0) lambda_max = std::max(lambda_max, cap / std::sqrt(e.smoothed[i]));
    double lo = 0.0, hi = lambda_max + 1.0;
    if (predicted(hi) <= goal)
        for (int i = 0; i < 64; ++i) {
            const double mid = 0.5 * (lo + hi);
            (predicted(mid) > goal ? lo : hi) = mid;
        }
    std::vector<std::uint32_t> next(pixels);
    for (std::size_t i = 0; i < pixels; ++i)
        next[i] = static_cast<std::uint32_t>(std::min(target(hi, i), std::ceil(growth * counts[i])));
    return next;
}

}  // namespace

TargetResult render_to_target(const Camera& camera, const RadianceSource& radiance, const ProgressiveSettings& settings,
                              const TargetSettings& target, const ProgressiveCallbacks& callbacks) {
    check_target(settings, target);
    ProgressiveRenderer renderer(camera, radiance, settings);
    const std::uint32_t first = settings.first_sample;
    const std::uint32_t cap = static_cast<std::uint32_t>(settings.spp);
    const std::uint32_t warm = std::min(cap, target.min_samples);

    ProgressiveCallbacks cb = callbacks;
    if (target.seconds > 0.0) {
        const auto budget = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(target.seconds));
        cb.deadline = std::min(callbacks.deadline, std::chrono::steady_clock::now() + budget);
    }
    auto interrupted = [&] { return callbacks.stop && callbacks.stop->load(); };
    auto out_of_time = [&] {
        return cb.deadline != std::chrono::steady_clock::time_point::max() &&
               std::chrono::steady_clock::now() >= cb.deadline;
    };

    TargetResult result;
    const SampleBuffer& buffer = renderer.buffer();
    std::uint32_t uniform = 0;  // the count of every pixel without adaptive sampling
    int pass = 0;
    for (;; ++pass) {
        // The next pass's counts: the warm-up doubling to `warm`, then as the estimate plans.
        std::vector<std::uint32_t> next;
        const double estimate = pass == 0 ? std::numeric_limits<double>::infinity() : error_estimate(buffer);
        if (uniform < warm) {
            uniform = std::min(warm, std::max(1u, 2 * uniform));
        } else {
            if (target.noise > 0.0 && estimate <= target.noise) {
                result.stop = TargetStop::noise;
                break;
            }
            if (buffer.min_count() >= cap) {
                result.stop = TargetStop::samples;
                break;
            }
            // The counts that reach the target by the model (a time budget alone: half the estimate), approached by
            // at most kGrowth times the samples per pass.
            const double goal = target.noise > 0.0 ? target.noise : estimate / 2.0;
            if (!target.adaptive) {
                const double factor = std::clamp(estimate / goal, 1.1, kGrowth);
                uniform = static_cast<std::uint32_t>(
                    std::min<double>(cap, std::max<double>(uniform + 1.0, std::ceil(uniform * factor))));
            } else {
                const std::vector<std::uint32_t> counts = buffer.counts();
                next = adaptive_counts(counts, pixel_errors(buffer), goal, cap, kGrowth);
                if (next == counts)  // the model says done where the estimate does not: a uniform step instead
                    for (std::uint32_t& n : next)
                        n = std::min(cap, std::max(n + 1, static_cast<std::uint32_t>(std::ceil(n * 1.25))));
            }
        }
        if (pass > 0 && out_of_time()) {
            result.stop = TargetStop::time;
            break;
        }
        bool complete = true;
        std::uint32_t pass_begin = first + buffer.min_count(), pass_end = first + uniform;
        if (pass == 0) {
            // The first pass, one sample per pixel, is not cut short by the time budget: no pixel stays black.
            ProgressiveCallbacks first_pass = cb;
            first_pass.deadline = callbacks.deadline;
            complete = renderer.render_to(first + uniform, first_pass, pass);
        } else if (next.empty()) {
            complete = renderer.render_to(first + uniform, cb, pass);
        } else {
            for (std::uint32_t& n : next) n += first;
            pass_end = *std::max_element(next.begin(), next.end());
            complete = renderer.render_to(next, cb, pass);
        }
        result.passes = pass + 1;
        if (!complete) {
            result.stop = interrupted() ? TargetStop::interrupted : TargetStop::time;
            break;
        }
        if (callbacks.pass) callbacks.pass(PassUpdate{pass, pass_begin, pass_end, buffer, renderer.stats()});
    }
    result.image = buffer.mean_image();
    result.buffer = buffer;
    result.stats = renderer.stats();
    result.stats.cancelled = result.stop == TargetStop::interrupted;
    result.estimate = error_estimate(buffer);
    return result;
}

}  // namespace rtlab
