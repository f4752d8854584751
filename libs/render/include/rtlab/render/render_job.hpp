#pragma once
/// \brief Everything one render needs, and the function that renders it.
#include <rtlab/render/camera.hpp>
#include <rtlab/render/photon_integrator.hpp>
#include <rtlab/render/radiance_source.hpp>
#include <rtlab/render/renderer.hpp>
#include <rtlab/render/scene.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/path.hpp>
#include <rtlab/shading/whitted.hpp>

#include <memory>
#include <vector>

namespace rtlab {

/// \brief One render: camera, scene, lights, integrator options and render settings.
struct RenderJob {
    std::shared_ptr<const Camera> camera;
    std::shared_ptr<const Scene> scene;
    std::vector<std::shared_ptr<const Light>> lights;
    WhittedOptions whitted;  ///< convention, depth, background or environment
    /// Which integrator renders: whitted reads `whitted`; direct and path read `path` and, from `whitted`, the
    /// background (a uniform environment light) or environment (looked up, not sampled) and the convention
    /// (physical only).
    IntegratorKind integrator = IntegratorKind::whitted;
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

private:
    const WhittedIntegrator& m_integrator;
};

/// \brief The direct or path integrator as the renderer's radiance source: numbers from the camera sample's
/// stream (low-discrepancy under the sobol pattern), or, for the other patterns, from an independent stream of the
/// sample's key.
class PathRadiance final : public RadianceSource {
public:
    PathRadiance(const PathIntegrator& integrator, IntegratorKind kind) : m_integrator(integrator), m_kind(kind) {}
    RGB radiance(const Ray& ray, const SampleKey& key, RayCounters& counters) const override {
        return estimate(ray, SampleStream(SampleSequence::independent, key), counters);
    }
    RGB sample_radiance(const CameraSample& sample, RayCounters& counters) const override {
        return estimate(sample.ray, sample.stream, counters);
    }

private:
    RGB estimate(const Ray& ray, const SampleStream& stream, RayCounters& counters) const {
        return m_kind == IntegratorKind::path ? m_integrator.path(ray, stream, counters)
                                              : m_integrator.direct(ray, stream, counters);
    }
    const PathIntegrator& m_integrator;
    IntegratorKind m_kind;
};

/// Renders a job: RenderResult::stats counts camera, shadow, reflected and refracted rays (photon rays among the
/// reflected and refracted), and its image is the same for any settings.threads. photon shoots its photons first
/// (settings.seed and threads; the stop flag ends that too), then renders with any pattern; sppm runs settings.spp
/// iterations (render_sppm: pattern sobol or random). Throws rtlab::Error for a job without camera or scene, a null
/// light, or bad settings (see render()).
RenderResult render_job(const RenderJob& job, const RenderCallbacks& callbacks = {});

}  // namespace rtlab
