#pragma once
/// \brief Everything one render needs, and the function that renders it.
#include <rtlab/render/camera.hpp>
#include <rtlab/render/radiance_source.hpp>
#include <rtlab/render/renderer.hpp>
#include <rtlab/render/scene.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/whitted.hpp>

#include <memory>
#include <vector>

namespace rtlab {

/// \brief One render: camera, scene, lights, integrator options and render settings.
struct RenderJob {
    std::shared_ptr<const Camera> camera;
    std::shared_ptr<const Scene> scene;
    std::vector<std::shared_ptr<const Light>> lights;
    WhittedOptions whitted;   ///< convention, depth, background or environment
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

/// Renders a job: RenderResult::stats counts camera, shadow, reflected and refracted rays, and its image is
/// the same for any settings.threads. Throws rtlab::Error for a job without camera or scene, a null light,
/// or bad settings (see render()).
RenderResult render_job(const RenderJob& job, const RenderCallbacks& callbacks = {});

}  // namespace rtlab
