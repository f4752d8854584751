#pragma once
/// \brief The radiance source of a render job (its integrator over its scene and lights), for the programs that
/// drive the progressive renderer themselves (a render to a noise target, a share of sample indices).
#include <rtlab/render/radiance_source.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sampled_lights.hpp>

#include <memory>
#include <optional>

namespace rtlab {

/// \brief Builds the job's integrator as render_job() does and keeps it, with what it refers to, alive (the job's
/// scene and lights are shared; the camera is not needed).
class JobRadiance {
public:
    /// Throws rtlab::Error as render_job() does for a job without camera or scene, a null light, or what the
    /// sampling integrators cannot honour.
    explicit JobRadiance(const RenderJob& job);
    JobRadiance(const JobRadiance&) = delete;
    JobRadiance& operator=(const JobRadiance&) = delete;

    /// Valid while this object lives.
    const RadianceSource& source() const { return *m_source; }

private:
    std::shared_ptr<const Scene> m_scene;  // the integrators refer to it
    std::optional<WhittedIntegrator> m_whitted;
    SampledLights m_sampled;
    std::optional<PathIntegrator> m_path;
    std::unique_ptr<RadianceSource> m_source;
};

}  // namespace rtlab
