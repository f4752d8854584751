#include "light_transport.hpp"
#include "tile_parallel.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/geometry/spawn.hpp>
#include <rtlab/render/photon_tracer.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace rtlab {

namespace {

// Photons per task: enough work to hide the task's cost, few enough that 2 threads stay busy to the end.
constexpr std::uint32_t kBlockPhotons = 1024;

constexpr std::uint32_t kChoicePair = 0, kPositionPair = 1, kDirectionPair = 2, kFirstBouncePair = 3;

// The ray a photon leaves its light along. A point on an emitting surface is off it by its sampling's rounding: the
// origin moves off by a bound relative to the point's coordinates (a few float steps), as spawn_ray does for hits.
Ray emission_ray(const EmissionSample& e) {
    if (glm::dot(e.normal, e.normal) > 0.0f) {
        const Vec3 error = (glm::abs(e.position) + Vec3(1e-3f)) * 1e-6f;
        return Ray{offset_ray_origin(e.position, error, e.normal, e.direction), e.direction, 0.0f, kInfinity};
    }
    return Ray{e.position, e.direction, 0.0f, kInfinity};
}

class PhotonShooter {
public:
    PhotonShooter(const SceneQuery& scene, const LightSet& lights, const SceneSphere& sphere,
                  const PhotonTraceSettings& settings)
        : m_scene(scene), m_lights(lights), m_sphere(sphere), m_settings(settings) {}

    void shoot(std::uint32_t index, std::vector<Photon>& out, RayStats& rays) const {
        const SampleStream stream(m_settings.sequence,
                                  SampleKey{m_settings.seed, kPhotonStreamX, m_settings.pass, index, 0});
        const LightSet::Entry* light = m_lights.choose(stream.get2d(kChoicePair).x);
        if (!light) return;
        const std::optional<EmissionSample> e =
            light->emitter->sample_le(stream.get2d(kPositionPair), stream.get2d(kDirectionPair), m_sphere);
        if (!e) return;
        RGB beta = e->power * (1.0f / light->probability);
        if (beta.is_black() || !beta.is_finite()) return;
        Ray ray = emission_ray(*e);
        ++rays.reflected;
        bool all_pass = true;  // every event so far a pass-through one (PhotonPath)
        for (int bounce = 0; bounce < m_settings.max_depth; ++bounce) {
            PathVertex v;
            if (!find_path_vertex(m_scene, ray, v)) return;
            beta *= v.absorbed;
            const Material& material = *v.info.material;
            const bool gather_vertex = detail::is_gather_vertex(v);
            if (gather_vertex && material.reflects_direct_light()) {
                const PhotonPath path = bounce == 0 ? PhotonPath::direct
                                        : all_pass  ? PhotonPath::caustic
                                                    : PhotonPath::indirect;
                if (m_settings.keep & (1u << static_cast<unsigned>(path)))
                    out.push_back(Photon{v.hit.point, v.wo, beta, static_cast<std::uint16_t>(bounce), path});
            }
            if (bounce + 1 >= m_settings.max_depth) return;
            const auto b = static_cast<std::uint32_t>(bounce);
            const Vec2 u_choice = stream.get2d(kFirstBouncePair + 2 * b);
            const std::optional<BsdfSample> s = material.sample(
                v.terms, v.wo_local, u_choice.x, stream.get2d(kFirstBouncePair + 2 * b + 1), TransportMode::importance);
            if (!s) return;
            const Vec3 wi = v.frame.to_world(s->wi);
            // The adjoint BSDF with shading normals (Veach 1997, 5.3): f* picks up |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|)
            // so that light is not gained or lost where the shading normal leans away from the true one.
            const float denominator = std::abs(glm::dot(v.wo, v.outward)) * std::abs(s->wi.z);
            const float correction = std::abs(v.wo_local.z) * std::abs(glm::dot(wi, v.outward)) / denominator;
            if (!(correction > 0.0f) || !std::isfinite(correction)) return;
            RGB next = beta * s->value * correction;
            if (m_settings.roulette) {
                const float before = channel_mean(beta);
                const float survival = before > 0.0f ? std::min(1.0f, channel_mean(next) / before) : 0.0f;
                if (!(u_choice.y < survival)) return;
                next *= 1.0f / survival;
            }
            beta = next;
            if (beta.is_black() || !beta.is_finite()) return;
            all_pass = all_pass && ((s->flags & kLobeSpecular) != 0 || !gather_vertex);
            if (s->flags & kLobeTransmission)
                ++rays.refracted;
            else
                ++rays.reflected;
            ray = spawn_ray(v.hit, wi);
        }
    }

private:
    const SceneQuery& m_scene;
    const LightSet& m_lights;
    SceneSphere m_sphere;
    const PhotonTraceSettings& m_settings;
};

}  // namespace

PhotonTrace trace_photons(const SceneQuery& scene, const LightSet& lights, const SceneSphere& sphere,
                          const PhotonTraceSettings& settings, const std::atomic<bool>* stop) {
    if (settings.max_depth < 0)
        throw Error("photon tracer: max_depth must be >= 0, got " + std::to_string(settings.max_depth));
    if (settings.threads < 0)
        throw Error("photon tracer: thread count must be >= 0, got " + std::to_string(settings.threads));
    const PhotonShooter shooter(scene, lights, sphere, settings);
    const std::uint32_t blocks = (settings.photons + kBlockPhotons - 1) / kBlockPhotons;
    struct Block {
        std::vector<Photon> photons;
        RayStats rays;
        bool done = false;
    };
    std::vector<Block> out(blocks);
    detail::for_each_tile(settings.threads, static_cast<int>(blocks), [&](int index) {
        if (stop && stop->load(std::memory_order_relaxed)) return;
        Block& block = out[static_cast<std::size_t>(index)];
        const std::uint32_t begin = static_cast<std::uint32_t>(index) * kBlockPhotons;
        const std::uint32_t end = std::min(settings.photons, begin + kBlockPhotons);
        for (std::uint32_t i = begin; i < end; ++i) shooter.shoot(i, block.photons, block.rays);
        block.done = true;
    });
    PhotonTrace trace;
    std::size_t total = 0;
    for (const Block& b : out) total += b.photons.size();
    trace.photons.reserve(total);
    for (Block& b : out) {
        trace.cancelled = trace.cancelled || !b.done;
        trace.photons.insert(trace.photons.end(), b.photons.begin(), b.photons.end());
        trace.rays += b.rays;
        std::vector<Photon>().swap(b.photons);
    }
    trace.shot = trace.cancelled ? 0 : settings.photons;
    return trace;
}

}  // namespace rtlab
