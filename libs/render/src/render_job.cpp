#include <rtlab/core/error.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sampled_lights.hpp>
#include <rtlab/render/sppm.hpp>

#include <string>

namespace rtlab {

RenderResult render_job(const RenderJob& job, const RenderCallbacks& callbacks) {
    if (!job.camera) throw Error("render job: no camera");
    if (!job.scene) throw Error("render job: no scene");
    for (std::size_t i = 0; i < job.lights.size(); ++i)
        if (!job.lights[i]) throw Error("render job: light " + std::to_string(i) + " is null");
    if (job.integrator == IntegratorKind::whitted) {
        const WhittedIntegrator integrator(*job.scene, job.lights, job.whitted);
        const WhittedRadiance source(integrator);
        return render(*job.camera, source, job.settings, callbacks);
    }
    const SampledLights sampled = make_sampled_lights(job.scene, job.lights, job.whitted);
    PathOptions options = job.path;
    if (!options.environment) options.environment = job.whitted.environment;
    if (job.integrator == IntegratorKind::sppm)
        return render_sppm(*job.camera, *sampled.scene, sampled.lights, sampled.sphere, options, job.photons,
                           job.settings, callbacks);
    if (job.integrator == IntegratorKind::photon) {
        const PhotonIntegrator integrator(*sampled.scene, sampled.lights, sampled.sphere, options, job.photons,
                                          job.settings.seed, job.settings.threads, callbacks.stop);
        RenderResult result;
        if (integrator.cancelled()) {
            // Stopped while shooting photons: no pixel was rendered.
            result.image = Image(job.camera->width(), job.camera->height());
            result.samples.assign(result.image.pixel_count(), 0);
            result.stats.cancelled = true;
        } else {
            result = render(*job.camera, integrator, job.settings, callbacks);
        }
        result.stats.rays += RayCounters{integrator.photon_rays(), 0};
        return result;
    }
    const PathIntegrator integrator(*sampled.scene, sampled.lights, options);
    const PathRadiance source(integrator, job.integrator);
    return render(*job.camera, source, job.settings, callbacks);
}

}  // namespace rtlab
