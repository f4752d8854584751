#include <rtlab/render/job_radiance.hpp>
#include <rtlab/render/render_job.hpp>

namespace rtlab {

RenderResult render_job(const RenderJob& job, const RenderCallbacks& callbacks) {
    const JobRadiance radiance(job);
    return render(*job.camera, radiance.source(), job.settings, callbacks);
}

}  // namespace rtlab
