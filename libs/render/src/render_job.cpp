#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sampled_lights.hpp>
#include <rtlab/render/sppm.hpp>

#include <algorithm>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

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

// A radiance source that owns the integrator (and what it refers to) that its Source calls.
template <class Owned, class Source>
class Owning final : public RadianceSource {
public:
    template <class MakeSource>
    Owning(std::unique_ptr<const Owned> owned, MakeSource make_source)
        : m_owned(std::move(owned)), m_source(make_source(*m_owned)) {}
    RGB radiance(const Ray& ray, const SampleKey& key, RayCounters& counters) const override {
        return m_source.radiance(ray, key, counters);
    }
    RGB sample_radiance(const CameraSample& sample, RayCounters& counters) const override {
        return m_source.sample_radiance(sample, counters);
    }
    void radiance_batch(std::span<const CameraSample> samples, std::span<RGB> out,
                        RayCounters& counters) const override {
        m_source.radiance_batch(samples, out, counters);
    }
    bool traces_batches() const override { return m_source.traces_batches(); }

private:
    std::unique_ptr<const Owned> m_owned;
    Source m_source;
};

// The path integrator with the lights and the scene it refers to.
struct SampledIntegrator {
    explicit SampledIntegrator(const RenderJob& job)
        : sampled(make_sampled_lights(job.scene, job.lights, job.whitted, job.environment)),
          integrator(*sampled.scene, sampled.lights, options(job)) {}
    static PathOptions options(const RenderJob& job) {
        PathOptions o = job.path;
        if (!o.environment) o.environment = job.whitted.environment;
        return o;
    }
    SampledLights sampled;
    PathIntegrator integrator;
};

void check_job(const RenderJob& job) {
    if (!job.camera) throw Error("render job: no camera");
    if (!job.scene) throw Error("render job: no scene");
    for (std::size_t i = 0; i < job.lights.size(); ++i)
        if (!job.lights[i]) throw Error("render job: light " + std::to_string(i) + " is null");
    if (job.environment && (job.whitted.environment || !job.whitted.background.is_black()))
        throw Error("render job: an environment light and a background or skybox; give one of them");
}

// The photon integrator with the lights and the scene it refers to: shoots the photons when made.
struct PhotonOwner {
    PhotonOwner(const RenderJob& job, const std::atomic<bool>* stop)
        : sampled(make_sampled_lights(job.scene, job.lights, job.whitted, job.environment)),
          integrator(*sampled.scene, sampled.lights, sampled.sphere, SampledIntegrator::options(job), job.photons,
                     job.settings.seed, job.settings.threads, stop) {}
    SampledLights sampled;
    PhotonIntegrator integrator;
};

// The caller has checked the job.
std::shared_ptr<const PhotonIntegrator> make_photon_integrator(const RenderJob& job, const std::atomic<bool>* stop) {
    auto owner = std::make_shared<const PhotonOwner>(job, stop);
    return {owner, &owner->integrator};
}

// The sppm renderer with the lights and the scene it refers to.
struct SppmOwner {
    SppmOwner(const RenderJob& job, const Camera& camera, const ProgressiveSettings& settings)
        : sampled(make_sampled_lights(job.scene, job.lights, job.whitted, job.environment)),
          renderer(camera, *sampled.scene, sampled.lights, sampled.sphere, SampledIntegrator::options(job), job.photons,
                   settings) {}
    SampledLights sampled;
    SppmRenderer renderer;
};

}  // namespace

void WhittedRadiance::radiance_batch(std::span<const CameraSample> samples, std::span<RGB> out,
                                     RayCounters& counters) const {
    // Pixels in runs of four columns over the group's rows (4 x 2 tiles of a two-row group), the order packets
    // want; each sample's radiance is its own whatever the order.
    const std::size_t n = samples.size();
    if (!m_integrator.traces_packets()) {
        for (std::size_t i = 0; i < n; ++i)
            out[i] = m_integrator.radiance(samples[i].ray, samples[i].stream.key(), counters);
        return;
    }
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
    auto place = [&](std::uint32_t i) {
        const SampleKey& k = samples[i].stream.key();
        return std::tuple(k.x >> 2, k.y, k.x, i);
    };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return place(a) < place(b); });
    std::vector<Ray> rays(n);
    std::vector<SampleKey> keys(n);
    std::vector<RGB> values(n);
    for (std::size_t k = 0; k < n; ++k) {
        rays[k] = samples[order[k]].ray;
        keys[k] = samples[order[k]].stream.key();
    }
    m_integrator.radiance_packet(rays, keys, values, counters);
    for (std::size_t k = 0; k < n; ++k) out[order[k]] = values[k];
}

std::shared_ptr<const RadianceSource> make_radiance_source(const RenderJob& job, IntegratorKind kind,
                                                           const std::atomic<bool>* stop) {
    check_job(job);
    switch (kind) {
        case IntegratorKind::whitted:
            return std::make_shared<const Owning<WhittedIntegrator, WhittedRadiance>>(
                std::make_unique<const WhittedIntegrator>(*job.scene, job.lights, whitted_options(job)),
                [](const WhittedIntegrator& integrator) { return WhittedRadiance(integrator); });
        case IntegratorKind::direct:
        case IntegratorKind::path:
            return std::make_shared<const Owning<SampledIntegrator, PathRadiance>>(
                std::make_unique<const SampledIntegrator>(job),
                [kind](const SampledIntegrator& owner) { return PathRadiance(owner.integrator, kind); });
        case IntegratorKind::photon:
            return make_photon_integrator(job, stop);
        case IntegratorKind::sppm:
            break;
    }
    throw Error(
        "render job: sppm is not a radiance source (its iterations change every pixel's estimate): render "
        "it with render_job or make_sppm_renderer");
}

std::shared_ptr<SppmRenderer> make_sppm_renderer(const RenderJob& job, const Camera& camera,
                                                 const ProgressiveSettings& settings) {
    check_job(job);
    auto owner = std::make_shared<SppmOwner>(job, camera, settings);
    return {owner, &owner->renderer};
}

WhittedOptions whitted_options(const RenderJob& job) {
    WhittedOptions options = job.whitted;
    if (job.environment) options.environment = std::make_shared<EnvironmentLookup>(job.environment);
    return options;
}

RenderResult render_job(const RenderJob& job, const RenderCallbacks& callbacks) {
    check_job(job);
    if (job.integrator == IntegratorKind::sppm) {
        const SampledLights sampled = make_sampled_lights(job.scene, job.lights, job.whitted, job.environment);
        return render_sppm(*job.camera, *sampled.scene, sampled.lights, sampled.sphere, SampledIntegrator::options(job),
                           job.photons, job.settings, callbacks);
    }
    if (job.integrator == IntegratorKind::photon) {
        const auto integrator = make_photon_integrator(job, callbacks.stop);
        RenderResult result;
        if (integrator->cancelled()) {
            // Stopped while shooting photons: no pixel was rendered.
            result.image = Image(job.camera->width(), job.camera->height());
            result.samples.assign(result.image.pixel_count(), 0);
            result.stats.cancelled = true;
        } else {
            result = render(*job.camera, *integrator, job.settings, callbacks);
        }
        result.stats.rays += RayCounters{integrator->photon_rays(), 0};
        return result;
    }
    const auto source = make_radiance_source(job, job.integrator);
    return render(*job.camera, *source, job.settings, callbacks);
}

}  // namespace rtlab
