#pragma once
/// \brief Stochastic progressive photon mapping (`sppm`; Hachisuka and Jensen 2009, after Hachisuka, Ogaki and
/// Jensen 2008): the consistent photon mapper, whose error goes to zero with iterations.
///
/// Iteration k (from 0):
///  1. camera pass: sample k of every pixel through the progressive renderer (ProgressiveRenderer, so sample streams,
///     tiles, callbacks, the stop flag and the per-pixel sums are the path tracer's). Each camera path goes on through
///     pass-through events (delta lobes, glossy-only surfaces: PhotonPath) to its first diffuse one, the visible
///     point, as photon's camera paths do (rtlab/render/photon_integrator.hpp). The sample's value is the direct
///     part: the light met on the way (emission; next-event estimation at the glossy vertices path traced) and
///     next-event estimation at the visible point with MIS against its own BSDF sample meeting a light. It is
///     averaged per pixel in direct(), a SampleBuffer like any progressive render's.
///  2. photon pass: PhotonOptions::photons photons of pass k (trace_photons), keeping those that made at least one
///     bounce (caustic and indirect: the light the direct part has not counted), and a kd-tree over them.
///  3. gather: each pixel with a visible point this iteration sums f(wo, photon.wi) photon.power over the photons
///     within its radius r (a radius search in the tree's order, photons of b bounces only when the path has at most
///     PathOptions::max_depth scattering events), M of them; then N' = N + alpha M, r' = r sqrt(N' / (N + M)),
///     tau' = (tau + weight sum) r'^2 / r^2 (the pixel's statistics, kept whatever its visible point).
/// The image after K iterations of P photons: direct mean + tau / (K P pi r^2) per pixel.
///
/// Deterministic: the camera pass is the progressive renderer's, the photons trace_photons', each pixel's sum runs in
/// the kd-tree's order and its statistics are updated by the pixel alone (no atomics), so the image is the same bytes
/// for any thread count. In a progressive program (a viewer) an iteration is a pass: call iterate() per pass and
/// show image(); the `tile` and `progress` callbacks come from the camera pass, `pass` after the gather.
#include <rtlab/core/image.hpp>
#include <rtlab/render/camera.hpp>
#include <rtlab/render/photon_integrator.hpp>
#include <rtlab/render/progressive.hpp>
#include <rtlab/render/renderer.hpp>
#include <rtlab/shading/light_set.hpp>
#include <rtlab/shading/path.hpp>
#include <rtlab/shading/scene_query.hpp>

#include <memory>
#include <vector>

namespace rtlab {

/// \brief A stochastic progressive photon mapping render in the making. The camera, scene and lights must outlive it.
class SppmRenderer {
public:
    /// settings: the camera pass's sequence, seed, tile size and threads (spp, first_sample and pass_samples are not
    /// read; iteration k is camera sample k). Throws rtlab::Error for bad options or settings, or an environment
    /// texture (it sends no photons).
    SppmRenderer(const Camera& camera, const SceneQuery& scene, const LightSet& lights, const SceneSphere& sphere,
                 PathOptions path, PhotonOptions options, const ProgressiveSettings& settings);
    ~SppmRenderer();
    SppmRenderer(const SppmRenderer&) = delete;
    SppmRenderer& operator=(const SppmRenderer&) = delete;

    /// Runs one more iteration. False when the stop flag ended it: nothing of it counts yet, and calling again
    /// resumes it (the camera pass keeps what it finished).
    bool iterate(const ProgressiveCallbacks& callbacks = {});
    /// Counts `iterations` more in the camera pass's RenderProgress::tiles_total (ProgressiveRenderer::plan_passes).
    void plan_iterations(int iterations);

    int iterations() const { return m_iterations; }
    /// The image so far: black before the first iteration.
    Image image() const;
    /// The direct part's per-pixel sums (one sample per pixel per iteration).
    const SampleBuffer& direct() const;
    /// Camera, shadow and photon rays (photon rays count as reflected or refracted) and the time in iterate().
    const RenderStats& stats() const { return m_stats; }
    std::uint64_t photons_shot() const;
    /// Pixel (x, y)'s current radius (0 before its first visible point) and photon count N.
    float radius(int x, int y) const;
    double photon_count(int x, int y) const;

private:
    struct State;
    std::unique_ptr<State> m_state;
    int m_iterations = 0;
    RenderStats m_stats;
};

/// Renders settings.spp iterations of sppm (RenderSettings: pattern sobol or random, the camera pass's sequence;
/// seed; threads; tile size), calling callbacks.progress through the camera passes and honouring callbacks.stop.
/// RenderResult::samples holds each pixel's iterations; buffer is null (the per-pixel sums are the direct part
/// only, no estimate of the whole image's noise). Throws rtlab::Error for another pattern or bad settings.
RenderResult render_sppm(const Camera& camera, const SceneQuery& scene, const LightSet& lights,
                         const SceneSphere& sphere, const PathOptions& path, const PhotonOptions& options,
                         const RenderSettings& settings, const RenderCallbacks& callbacks = {});

}  // namespace rtlab
