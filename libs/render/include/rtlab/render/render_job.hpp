#pragma once
/// \brief Everything one render needs, and the function that renders it.
#include <rtlab/render/camera.hpp>
#include <rtlab/render/photon_integrator.hpp>
#include <rtlab/render/radiance_source.hpp>
#include <rtlab/render/renderer.hpp>
#include <rtlab/render/scene.hpp>
#include <rtlab/render/sppm.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/path.hpp>
#include <rtlab/shading/whitted.hpp>

#include <atomic>
#include <memory>
#include <vector>

namespace rtlab {

/// \brief One render: camera, scene, lights, integrator options and render settings.
struct RenderJob {
    std::shared_ptr<const Camera> camera;
    std::shared_ptr<const Scene> scene;
    std::vector<std::shared_ptr<const Light>> lights;
    WhittedOptions whitted;  ///< convention, depth, background or environment
    /// Which integrator renders: whitted reads `whitted`; direct, path, photon and sppm read `path` (photon and sppm
    /// also `photons`) and, from `whitted`, the
    /// background (a uniform environment light) or environment (looked up, not sampled) and the convention
    /// (physical only).
    IntegratorKind integrator = IntegratorKind::whitted;
    /// An environment light (an EnvironmentMap, say), instead of whitted's background and environment: what rays
    /// that escape see under every integrator, and a light that direct and path sample (with multiple importance
    /// sampling) and that photon and sppm shoot photons from. Its power is set for the scene's size when the render
    /// starts (for_scene_radius).
    std::shared_ptr<const EnvironmentEmitter> environment;
    PathOptions path;         ///< direct, path, photon, sppm
    PhotonOptions photons;    ///< photon, sppm
    RenderSettings settings;  ///< pattern, spp, adaptive, seed, threads
};

/// \brief The Whitted integrator as the renderer's radiance source: its shadow, reflected and refracted
/// rays go straight into the renderer's counters (RayCounters is RayStats plus the camera rays).
class WhittedRadiance final : public RadianceSource {
public:
    explicit WhittedRadiance(const WhittedIntegrator& integrator) : m_integrator(integrator) {}
    RGB radiance(const Ray& ray, const SampleKey& key, RayCounters& counters) const override {
        return m_integrator.radiance(ray, key, counters);
    }
    /// The group's camera rays through WhittedIntegrator::radiance_packet, in 4 x 2 pixel tiles where the group
    /// spans two rows.
    void radiance_batch(std::span<const CameraSample> samples, std::span<RGB> out,
                        RayCounters& counters) const override;
    /// When the scene has packets for some of its objects (WhittedIntegrator::traces_packets).
    bool traces_batches() const override { return m_integrator.traces_packets(); }

private:
    const WhittedIntegrator& m_integrator;
};

/// \brief The direct or path integrator as the renderer's radiance source: numbers from the camera sample's
/// stream (low-discrepancy under the sobol pattern), or, for the other patterns, from an independent stream of the
/// sample's key.
class PathRadiance final : public StreamRadianceSource {
public:
    PathRadiance(const PathIntegrator& integrator, IntegratorKind kind) : m_integrator(integrator), m_kind(kind) {}
    RGB estimate(const Ray& ray, const SampleStream& stream, RayStats& stats) const override {
        return m_kind == IntegratorKind::path ? m_integrator.path(ray, stream, stats)
                                              : m_integrator.direct(ray, stream, stats);
    }

private:
    const PathIntegrator& m_integrator;
    IntegratorKind m_kind;
};

/// The job's Whitted options with its environment light, if any, as the environment looked up by escaping rays
/// (what the whitted integrator of render_job and of the viewer use).
WhittedOptions whitted_options(const RenderJob& job);

/// The radiance source of `kind` for a job, owning the integrator it calls and whatever that refers to (for direct,
/// path and photon, the sampled lights and the scene with the area lights' quads): what render_job renders with, for
/// a program that renders a job its own way (progressively, to a noise target, in shares, in the viewer). photon
/// shoots its photons and builds its maps here (job.settings.seed and threads); a `stop` flag seen meanwhile leaves
/// the maps empty, so a caller that passes one must stop too once it is set. sppm is no radiance source (an
/// iteration changes every pixel's estimate): it throws rtlab::Error, see make_sppm_renderer. Throws rtlab::Error
/// as render_job does for the job's contents.
std::shared_ptr<const RadianceSource> make_radiance_source(const RenderJob& job, IntegratorKind kind,
                                                           const std::atomic<bool>* stop = nullptr);

/// sppm for a job, its iterations driven by the caller (SppmRenderer::iterate per pass, as the viewer does), owning
/// the sampled lights and scene it refers to; settings as SppmRenderer's. The camera must outlive it. Throws
/// rtlab::Error as SppmRenderer and render_job do.
std::shared_ptr<SppmRenderer> make_sppm_renderer(const RenderJob& job, const Camera& camera,
                                                 const ProgressiveSettings& settings);

/// Renders a job: RenderResult::stats counts camera, shadow, reflected and refracted rays (photon rays among the
/// reflected and refracted), and its image is the same for any settings.threads. photon shoots its photons first
/// (settings.seed and threads; the stop flag ends that too), then renders with any pattern; sppm runs settings.spp
/// iterations (render_sppm: pattern sobol or random). Throws rtlab::Error for a job without camera or scene, a null
/// light, an environment light beside whitted's background or environment, or bad settings (see render()).
RenderResult render_job(const RenderJob& job, const RenderCallbacks& callbacks = {});

}  // namespace rtlab
