#pragma once
/// \brief Rendering to a noise target or a time budget: progressive passes until the relative mean squared error,
/// estimated from the even and odd half-images, falls below a target; optionally spending each pass where the
/// estimate is noisy (adaptive sampling).
///
/// The error measure (relMSE): the mean over pixels and over the R, G and B channels of (I - R)^2 / (R^2 + eps),
/// eps = kRelMseEps, I the image and R the converged one. It is estimated without R from the two half-images (the
/// even and the odd samples of each pixel, SampleSums); the halves must be independent estimates of the pixel
/// (SampleSequence::sobol_halves or independent, not sobol: rtlab/core/sample_stream.hpp says why).
#include <rtlab/core/image.hpp>
#include <rtlab/render/progressive.hpp>
#include <rtlab/render/sample_buffer.hpp>
#include <rtlab/shading/path.hpp>

#include <cstdint>
#include <string>

namespace rtlab {

/// The eps of relMSE: keeps black pixels from dividing by zero and dark ones from ruling the mean.
inline constexpr double kRelMseEps = 0.01;

/// relMSE of `image` against `reference` (same size; throws rtlab::Error otherwise): mean over pixels and R, G, B
/// of (image - reference)^2 / (reference^2 + kRelMseEps).
double relative_mse(const Image& image, const Image& reference);

/// The estimate of pixel (x, y)'s relMSE term (its mean over R, G, B) from its half-images; +infinity while a half
/// holds no sample.
double pixel_error_estimate(const SampleBuffer& buffer, int x, int y);
/// The estimate of the image's relMSE: the mean of pixel_error_estimate over the pixels.
double error_estimate(const SampleBuffer& buffer);

/// Whether a render to a noise target may use this integrator: the half-image estimate sees only the variance of
/// an estimator whose samples are independent and unbiased for the converged image. True for whitted (each sample
/// is an independent estimate of the pixel's box-filtered Whitted radiance: what --noise bounds is the error
/// against that image, aliasing and area-light noise, not against physical light transport), direct and path; a
/// photon map shared by all samples would hide its bias from the halves.
bool supports_noise_target(IntegratorKind kind);

/// \brief What to render to.
struct TargetSettings {
    double noise = 0.0;    ///< the relMSE to reach (> 0), or 0: none
    double seconds = 0.0;  ///< the time budget (> 0), or 0: none; at least one of the two must be given
    /// Adaptive sampling: after the first min_samples, each pass gives more samples to the pixels whose estimated
    /// error is largest (see render_to_target). Off: every pixel gets the same samples.
    bool adaptive = true;
    /// Samples every pixel gets before the estimate is trusted (a stop by noise needs this many in every pixel): at
    /// least 2, one per half. 4 lets a coarse target (relMSE 0.05 on the Cornell box at 32x32 needs about 4) stop
    /// where it is reached; rare bright paths are no better found by a larger minimum than by the target itself.
    std::uint32_t min_samples = 4;
};

/// Why render_to_target stopped.
enum class TargetStop {
    noise,        ///< the estimate fell to the target
    samples,      ///< every pixel holds the cap (settings.spp)
    time,         ///< the time budget ran out (possibly within a pass)
    interrupted,  ///< the stop flag was set (stats.cancelled)
};
std::string target_stop_name(TargetStop stop);

/// \brief What render_to_target made.
struct TargetResult {
    Image image;  ///< buffer.mean_image()
    SampleBuffer buffer;
    RenderStats stats;      ///< cancelled only when interrupted
    double estimate = 0.0;  ///< error_estimate(buffer) at the end
    TargetStop stop = TargetStop::samples;
    int passes = 0;
};

/// Renders samples [settings.first_sample, ...) of every pixel in passes until the estimate is at most
/// target.noise, target.seconds have passed, every pixel holds settings.spp samples (the cap), or the stop flag is
/// set. Passes: every pixel to 1 sample (never cut short by the time budget, so no pixel stays black), then doubling
/// to min_samples; then each pass aims at the counts that bring the estimate to target.noise (a time budget alone: to
/// half the estimate) by the estimate's own model, pixel p's error falling as v_p / n_p, and goes at most twice the
/// way there (no pixel's count more than doubles in a pass). Without adaptive sampling every pixel gets the same
/// count (at least 1.1 times the last). With it, pixel p is given n_p = lambda sqrt(v_p) samples, never fewer than
/// it holds (the counts that minimise the samples for a given mean error), lambda set by bisection, v_p taken from
/// the pixel's 8 neighbours, not from the pixel itself (a pixel's own estimate steering its own samples biases the
/// estimate at the stop low; the neighbours' mean also has 8 times the degrees of freedom). Every decision is made
/// between passes from the sums alone, so without a time budget the result is the same bytes for any thread count
/// and tile size. Throws rtlab::Error for bad settings (neither noise nor time, the sobol sequence, a cap below 1);
/// callbacks as render_progressive's, with `pass` after each pass.
TargetResult render_to_target(const Camera& camera, const RadianceSource& radiance, const ProgressiveSettings& settings,
                              const TargetSettings& target, const ProgressiveCallbacks& callbacks = {});

}  // namespace rtlab
