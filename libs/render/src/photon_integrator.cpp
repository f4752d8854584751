#include "light_transport.hpp"
#include "tile_parallel.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/geometry/spawn.hpp>
#include <rtlab/render/photon_integrator.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace rtlab {

using detail::GatherHit;
using detail::GatherPoint;

void check_photon_options(const PhotonOptions& o) {
    if (o.photons < 1) throw Error("photons: count must be >= 1");
    if (o.nearest < 1) throw Error("photons: nearest must be >= 1, got " + std::to_string(o.nearest));
    if (!(o.max_radius >= 0.0f) || !std::isfinite(o.max_radius))
        throw Error("photons: max_radius must be >= 0 and finite (0: from the scene's size)");
    if (o.gather < 0) throw Error("photons: gather must be >= 0, got " + std::to_string(o.gather));
    if (!(o.radius >= 0.0f) || !std::isfinite(o.radius))
        throw Error("photons: radius must be >= 0 and finite (0: from the pixel footprint)");
    if (!(o.alpha > 0.0f && o.alpha < 1.0f)) throw Error("photons: alpha must be in (0, 1)");
}

namespace {

// The k-NN heap of a density estimate, one per thread: searches allocate nothing.
std::span<PointNeighbor> scratch(int k) {
    thread_local std::vector<PointNeighbor> buffer;
    buffer.resize(static_cast<std::size_t>(k));
    return buffer;
}

}  // namespace

PhotonIntegrator::PhotonIntegrator(const SceneQuery& scene, const LightSet& lights, const SceneSphere& sphere,
                                   PathOptions path, PhotonOptions options, std::uint64_t seed, int threads,
                                   const std::atomic<bool>* stop)
    : m_scene(scene), m_lights(lights), m_path(std::move(path)), m_options(options) {
    check_photon_options(m_options);
    if (m_path.max_depth < 0) throw Error("photon: max_depth must be >= 0");
    if (m_path.environment)
        throw Error("skybox: an environment texture sends no photons; photon mapping needs a 'background' colour");
    m_max_radius = m_options.max_radius > 0.0f ? m_options.max_radius : sphere.radius / 20.0f;
    PhotonTraceSettings trace;
    trace.photons = m_options.photons;
    trace.seed = seed;
    trace.max_depth = m_path.max_depth;
    trace.roulette = m_path.roulette;
    trace.keep = kKeepCaustic | kKeepIndirect | (m_options.gather > 0 ? kKeepDirect : 0u);
    trace.threads = threads;
    PhotonTrace shot = trace_photons(scene, lights, sphere, trace, stop);
    m_photon_rays = shot.rays;
    if (shot.cancelled) {
        m_cancelled = true;
        return;
    }
    m_shot = shot.shot;
    std::vector<Photon> caustic, global;
    for (const Photon& p : shot.photons) {
        if (p.path == PhotonPath::caustic) caustic.push_back(p);
        if (m_options.gather > 0 || p.path == PhotonPath::indirect) global.push_back(p);
    }
    std::vector<Photon>().swap(shot.photons);
    detail::run_on_threads(threads, [&] {
        m_caustic = PhotonMap(std::move(caustic));
        m_global = PhotonMap(std::move(global));
    });
}

// The reflected radiance at v from one map's photons that make paths of at most max_depth scattering events with
// v at scattering index `bounce`; per photon shot.
RGB PhotonIntegrator::density(const PhotonMap& map, const PathVertex& v, std::uint32_t bounce) const {
    if (map.empty() || m_shot == 0) return {};
    const long allowed = static_cast<long>(m_path.max_depth) - static_cast<long>(bounce) - 1;
    if (allowed < 0) return {};
    const Material& material = *v.info.material;
    const RGB sum = map.estimate(v.hit.point, m_max_radius * m_max_radius, m_options.filter, scratch(m_options.nearest),
                                 [&](const Photon& p) -> RGB {
                                     if (p.bounces > allowed) return {};
                                     const Vec3 wi = v.frame.to_local(p.wi);
                                     return material.eval(v.terms, v.wo_local, wi, TransportMode::radiance) * p.power;
                                 });
    return sum * (1.0f / static_cast<float>(m_shot));
}

// A final gather ray from the gather point: through pass-through events (walk_to_gather_point, counting no light on
// the way: next-event estimation at the gather point has the light met directly, the caustic map the light met
// through pass-through events alone) to the global map at the next gather point, which holds every photon there (all
// the light it reflects). `start.beta` includes the gather point's BSDF sample.
RGB PhotonIntegrator::gather_ray(const detail::WalkStart& start, const SampleStream& stream, RayStats& stats) const {
    std::optional<GatherPoint> y;
    RGB L = detail::walk_to_gather_point(m_scene, m_lights, m_path, start, stream, stats, y);
    if (y) L += y->weight() * density(m_global, y->v, y->bounce);
    return L;
}

RGB PhotonIntegrator::estimate(const Ray& camera_ray, const SampleStream& stream, RayStats& stats) const {
    std::optional<GatherPoint> gp;
    RGB L = detail::walk_to_gather_point(m_scene, m_lights, m_path, detail::WalkStart{camera_ray}, stream, stats, gp);
    if (!gp) return L;
    GatherHit first;
    L += detail::direct_at_gather_point(m_scene, m_lights, m_path, *gp, stream, stats, first);
    const RGB weight = gp->weight();
    L += weight * density(m_caustic, gp->v, gp->bounce);
    if (m_options.gather == 0) return L + weight * density(m_global, gp->v, gp->bounce);
    // The first gather ray is the gather point's own sample (already traced for the direct light's MIS); the others
    // draw the vertex's mixture again from streams of their own (the sample key's bounce field numbers them) and count
    // only when they draw a non-delta lobe, weighed by 1 / chance as the point itself is.
    RGB indirect = gather_ray(detail::WalkStart{first.ray, gp->beta * gp->sample.value, gp->bounce + 1, false, &first},
                              stream, stats);
    const PathVertex& v = gp->v;
    for (int g = 1; g < m_options.gather; ++g) {
        SampleKey key = stream.key();
        key.bounce = static_cast<std::uint32_t>(g);
        const SampleStream own(SampleSequence::independent, key);
        const std::optional<BsdfSample> s =
            v.info.material->sample(v.terms, v.wo_local, own.get2d(path_pair(gp->bounce, 3)).x,
                                    own.get2d(path_pair(gp->bounce, 2)), TransportMode::radiance);
        if (!s || (s->flags & kLobeSpecular)) continue;
        if (s->flags & kLobeTransmission)
            ++stats.refracted;
        else
            ++stats.reflected;
        const Ray ray = spawn_ray(v.hit, v.frame.to_world(s->wi));
        indirect += gather_ray(detail::WalkStart{ray, weight * s->value, gp->bounce + 1, false}, own, stats);
    }
    return L + indirect * (1.0f / static_cast<float>(m_options.gather));
}

}  // namespace rtlab
