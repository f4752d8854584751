#include <rtlab/core/error.hpp>
#include <rtlab/render/job_radiance.hpp>

#include <string>

namespace rtlab {

JobRadiance::JobRadiance(const RenderJob& job) {
    if (!job.camera) throw Error("render job: no camera");
    if (!job.scene) throw Error("render job: no scene");
    for (std::size_t i = 0; i < job.lights.size(); ++i)
        if (!job.lights[i]) throw Error("render job: light " + std::to_string(i) + " is null");
    m_scene = job.scene;
    if (job.integrator == IntegratorKind::whitted) {
        m_whitted.emplace(*job.scene, job.lights, job.whitted);
        m_source = std::make_unique<WhittedRadiance>(*m_whitted);
        return;
    }
    m_sampled = make_sampled_lights(job.scene, job.lights, job.whitted);
    PathOptions options = job.path;
    if (!options.environment) options.environment = job.whitted.environment;
    m_path.emplace(*m_sampled.scene, m_sampled.lights, options);
    m_source = std::make_unique<PathRadiance>(*m_path, job.integrator);
}

}  // namespace rtlab
