#include <rtlab/core/error.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sampled_lights.hpp>

#include <string>

namespace rtlab {

namespace {

// An environment light as the texture the Whitted integrator looks up for rays that escape.
class EnvironmentLookup final : public Texture {
public:
    explicit EnvironmentLookup(std::shared_ptr<const EnvironmentEmitter> environment)
        : m_environment(std::move(environment)) {}
    RGB eval(const TextureLookup& lookup) const override { return m_environment->radiance(lookup.direction); }

private:
    std::shared_ptr<const EnvironmentEmitter> m_environment;
};

}  // namespace

WhittedOptions whitted_options(const RenderJob& job) {
    WhittedOptions options = job.whitted;
    if (job.environment) options.environment = std::make_shared<EnvironmentLookup>(job.environment);
    return options;
}

RenderResult render_job(const RenderJob& job, const RenderCallbacks& callbacks) {
    if (!job.camera) throw Error("render job: no camera");
    if (!job.scene) throw Error("render job: no scene");
    for (std::size_t i = 0; i < job.lights.size(); ++i)
        if (!job.lights[i]) throw Error("render job: light " + std::to_string(i) + " is null");
    if (job.environment && (job.whitted.environment || !job.whitted.background.is_black()))
        throw Error("render job: an environment light and a background or skybox; give one of them");
    if (job.integrator == IntegratorKind::whitted) {
        const WhittedIntegrator integrator(*job.scene, job.lights, whitted_options(job));
        const WhittedRadiance source(integrator);
        return render(*job.camera, source, job.settings, callbacks);
    }
    const SampledLights sampled = make_sampled_lights(job.scene, job.lights, job.whitted, job.environment);
    PathOptions options = job.path;
    if (!options.environment) options.environment = job.whitted.environment;
    const PathIntegrator integrator(*sampled.scene, sampled.lights, options);
    const PathRadiance source(integrator, job.integrator);
    return render(*job.camera, source, job.settings, callbacks);
}

}  // namespace rtlab
