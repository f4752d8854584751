#include <rtlab/core/error.hpp>
#include <rtlab/render/render_job.hpp>

#include <string>

namespace rtlab {

RenderResult render_job(const RenderJob& job, const RenderCallbacks& callbacks) {
    if (!job.camera) throw Error("render job: no camera");
    if (!job.scene) throw Error("render job: no scene");
    for (std::size_t i = 0; i < job.lights.size(); ++i)
        if (!job.lights[i]) throw Error("render job: light " + std::to_string(i) + " is null");
    const WhittedIntegrator integrator(*job.scene, job.lights, job.whitted);
    const WhittedRadiance source(integrator);
    return render(*job.camera, source, job.settings, callbacks);
}

}  // namespace rtlab
