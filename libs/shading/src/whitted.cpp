#include "shading_frame.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/core/frame.hpp>
#include <rtlab/geometry/spawn.hpp>
#include <rtlab/shading/optics.hpp>
#include <rtlab/shading/whitted.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace rtlab {

namespace {

using shading_detail::exp_rgb;
using shading_detail::shading_frame;

// A smooth normal can send a reflection below the true surface (or a refraction above it), where it would
// start inside the object and leak light. Such a direction is mirrored in the true tangent plane, which
// keeps its tangential part; `side` is +1 for "above ng" (reflection) and -1 for "below" (refraction).
Vec3 keep_on_side(Vec3 dir, const Normal3& ng, float side) {
    const float c = glm::dot(dir, ng) * side;
    if (c > 0.0f) return dir;
    dir -= 2.0f * glm::dot(dir, ng) * ng;
    if (glm::dot(dir, ng) * side <= 0.0f) dir += side * 1e-3f * ng;  // exactly in the plane
    return glm::normalize(dir);
}

// The true normal of the hit turned towards where the ray (of unit direction d) came from, as shade() turns it.
Normal3 facing_normal(const Vec3& d, const SurfaceHit& hit, const SurfaceInfo& info) {
    const Normal3 ng = info.flags.reversed ? -hit.geometric_normal : hit.geometric_normal;
    return glm::dot(d, ng) < 0.0f ? ng : -ng;
}

// Whether a light sample brings light to the side of the surface ng (facing the viewer) points to: light from below
// the true surface would have to pass through it.
bool lights_surface(const LightSample& s, const Normal3& ng) {
    return !s.arriving.is_black() && glm::dot(s.wi, ng) > 0.0f;
}

}  // namespace

WhittedIntegrator::WhittedIntegrator(const SceneQuery& scene, std::vector<std::shared_ptr<const Light>> lights,
                                     WhittedOptions options)
    : m_scene(scene), m_lights(std::move(lights)), m_options(std::move(options)) {
    for (std::size_t i = 0; i < m_lights.size(); ++i)
        if (!m_lights[i]) throw Error("whitted: light " + std::to_string(i) + " is null");
    for (const auto& light : m_lights)
        m_entries.push_back({light.get(), light->ambient(), light->sample_count(), light->uses_random_sample()});
    if (m_options.max_depth < 0) throw Error("whitted: max_depth must be >= 0");
    if (!(m_options.min_weight >= 0.0f)) throw Error("whitted: min_weight must be >= 0");
}

RGB WhittedIntegrator::radiance(const Ray& ray, const SampleKey& key, RayStats& stats) const {
    return trace(ray, key, 0, 0, 1.0f, stats);
}

RGB WhittedIntegrator::escaped(const Ray& ray) const {
    if (!m_options.environment) return m_options.background;
    TextureLookup q;
    q.direction = ray.direction;
    return m_options.environment->eval(q);
}

RGB WhittedIntegrator::transmittance(const SurfaceHit& from, const LightSample& light, RayStats& stats) const {
    return transmittance(from, light, stats, kNotTraced);
}

RGB WhittedIntegrator::transmittance(const SurfaceHit& from, const LightSample& light, RayStats& stats,
                                     std::uint8_t known) const {
    auto segment = [&light](const SurfaceHit& h) {
        return light.at_infinity ? spawn_ray(h, light.wi) : spawn_ray_to(h, light.position);
    };
    Ray ray = segment(from);
    ++stats.shadow;
    RGB through(1.0f);
    Point3 last = from.point;  // distances between the hit points themselves, free of the spawn offsets
    // The first segment spans the whole way to the light, so it alone asks about opaque casters; the later
    // ones start at a transmissive surface crossed on it.
    for (int i = 0;; ++i) {
        SurfaceHit h;
        SurfaceInfo info;
        const ShadowHit met = i == 0 && known != kNotTraced
                                  ? (known == kBlocked ? ShadowHit::opaque : m_scene.shadow(ray, false, h, info))
                                  : m_scene.shadow(ray, i == 0, h, info);
        if (met == ShadowHit::opaque) return {};
        if (met == ShadowHit::clear || i >= m_options.max_crossings) return through;
        TextureLookup q;
        q.uv = h.uv;
        q.point = h.object_point;  // solid textures in object space, also through instances
        q.direction = ray.direction;
        RGB c = info.material->shadow_transmittance(q);
        const RGB& sigma = info.material->absorption();
        if (!sigma.is_black()) {
            // Leaving the medium: the stretch since the last crossing (or the start) was inside it.
            const Normal3 outward = info.flags.reversed ? -h.geometric_normal : h.geometric_normal;
            if (glm::dot(ray.direction, outward) > 0.0f) c *= exp_rgb(sigma * -glm::length(h.point - last));
        }
        last = h.point;
        through *= c;
        if (through.is_black()) return through;
        ray = segment(h);
        ++stats.shadow;
        if (i + 1 >= m_options.max_crossings) return through;
    }
}

RGB WhittedIntegrator::trace(const Ray& ray, const SampleKey& key, int depth, int crossings, float weight,
                             RayStats& stats) const {
    const float dlen = glm::length(ray.direction);
    if (!(dlen > 0.0f) || !std::isfinite(dlen)) return {};
    SurfaceHit hit;
    SurfaceInfo info;
    if (!m_scene.intersect_surface(ray, hit, info)) return escaped(ray);
    return shade(ray, dlen, hit, info, key, depth, crossings, weight, stats);
}

void WhittedIntegrator::radiance_packet(std::span<const Ray> rays, std::span<const SampleKey> keys, std::span<RGB> out,
                                        RayStats& stats) const {
    if (!m_scene.traces_packets()) {
        for (std::size_t i = 0; i < rays.size(); ++i) out[i] = radiance(rays[i], keys[i], stats);
        return;
    }
    // trace() at depth 0 for each ray, the scene asked about the rays with a direction all at once.
    constexpr std::size_t kChunk = 16;
    std::array<Ray, kChunk> traced;
    std::array<std::size_t, kChunk> index;
    std::array<SurfaceHit, kChunk> hits;
    std::array<SurfaceInfo, kChunk> infos;
    std::array<std::uint8_t, kChunk> found;
    std::array<float, kChunk> lengths;
    std::array<KnownLight, kChunk * kPacketLights> known;
    std::array<Ray, kChunk> shadows;
    std::array<std::size_t, kChunk> which;
    std::array<std::uint8_t, kChunk> blocked;
    for (std::size_t first = 0; first < rays.size(); first += kChunk) {
        const std::size_t end = std::min(rays.size(), first + kChunk);
        std::size_t n = 0;
        for (std::size_t i = first; i < end; ++i) {
            const float dlen = glm::length(rays[i].direction);
            if (!(dlen > 0.0f) || !std::isfinite(dlen)) {
                out[i] = {};
                continue;
            }
            traced[n] = rays[i];
            lengths[n] = dlen;
            hits[n] = SurfaceHit{};
            index[n++] = i;
        }
        m_scene.intersect_surface_packet(std::span<const Ray>(traced.data(), n), std::span<SurfaceHit>(hits.data(), n),
                                         std::span<SurfaceInfo>(infos.data(), n),
                                         std::span<std::uint8_t>(found.data(), n));
        // Each of the first kPacketLights lights that take no random number (point, spot, directional lights) sampled
        // at each hit whose shading will ask (a surface lit directly), as shade() would, and the first shadow
        // segments of the samples that light their surfaces traced together: shade() takes both as they are.
        const std::size_t packet_lights = std::min(m_entries.size(), kPacketLights);
        for (std::size_t j = 0; j < packet_lights; ++j) {
            const LightEntry& light = m_entries[j];
            if (light.sample_count != 1 || light.uses_random_sample) {
                for (std::size_t k = 0; k < n; ++k) known[k * kPacketLights + j].sampled = false;
                continue;
            }
            std::size_t count = 0;
            for (std::size_t k = 0; k < n; ++k) {
                KnownLight& kl = known[k * kPacketLights + j];
                kl.sampled = found[k] && infos[k].material->reflects_direct_light();
                if (!kl.sampled) continue;
                kl.sample = light.light->sample(hits[k].point, 0, Vec2(0.5f), m_options.convention);
                kl.lit = lights_surface(kl.sample, facing_normal(traced[k].direction / lengths[k], hits[k], infos[k]));
                if (!kl.lit) continue;
                shadows[count] = kl.sample.at_infinity ? spawn_ray(hits[k], kl.sample.wi)
                                                       : spawn_ray_to(hits[k], kl.sample.position);
                which[count++] = k;
            }
            if (count == 0) continue;
            m_scene.occluded_packet(std::span<const Ray>(shadows.data(), count),
                                    std::span<std::uint8_t>(blocked.data(), count));
            for (std::size_t c = 0; c < count; ++c) known[which[c] * kPacketLights + j].shadow = blocked[c];
        }
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t i = index[k];
            out[i] = found[k] ? shade(rays[i], lengths[k], hits[k], infos[k], keys[i], 0, 0, 1.0f, stats,
                                      known.data() + k * kPacketLights)
                              : escaped(rays[i]);
        }
    }
}

[[gnu::always_inline]] inline RGB WhittedIntegrator::shade(const Ray& ray, float dlen, const SurfaceHit& hit,
                                                           const SurfaceInfo& info, const SampleKey& key, int depth,
                                                           int crossings, float weight, RayStats& stats,
                                                           const KnownLight* known) const {
    const Material& material = *info.material;
    const Vec3 d = ray.direction / dlen;
    const Vec3 wo = -d;

    Normal3 ng = info.flags.reversed ? -hit.geometric_normal : hit.geometric_normal;
    Normal3 ns = info.flags.reversed ? -hit.shading_normal : hit.shading_normal;
    const bool entering = glm::dot(d, ng) < 0.0f;  // as facing_normal() decides
    // Both sides shade: turn the normals towards the viewer. A shading normal still facing away (a smooth
    // normal at a silhouette) gives way to the true one.
    if (!entering) {
        ng = -ng;
        ns = -ns;
    }
    if (!(glm::dot(ns, wo) > 0.0f) || !is_finite(ns)) ns = ng;

    TextureLookup q;
    q.uv = hit.uv;
    q.point = hit.object_point;
    q.direction = d;
    const SurfaceTerms t = material.terms(q);

    // A cut-out lets 1 - opacity through, as if the surface were not there (not counted as a bounce).
    RGB behind;
    if (t.opacity < 1.0f && crossings < m_options.max_crossings) {
        const float w = weight * (1.0f - t.opacity);
        ++stats.refracted;
        behind = (1.0f - t.opacity) * trace(spawn_ray(hit, d), key, depth, crossings + 1, w, stats);
        if (t.opacity <= 0.0f) return behind;
    }

    RGB L = t.emission;
    if (material.reflects_direct_light()) {
        const Frame frame = shading_frame(ns, hit.tangent);
        const Vec3 wo_local = frame.to_local(wo);
        SampleKey here = key;  // children get the caller's key and add their own depth
        here.bounce += static_cast<std::uint32_t>(depth);
        std::uint32_t dim = kLightDimension;
        for (std::size_t j = 0; j < m_entries.size(); ++j) {
            const LightEntry& light = m_entries[j];
            L += t.diffuse * light.ambient;
            // radiance_packet's sample (a light taking one sample without a random number) and its shadow answer.
            const KnownLight* pre = known && j < kPacketLights && known[j].sampled ? &known[j] : nullptr;
            const int n = light.sample_count;
            for (int i = 0; i < n; ++i, dim += 2) {
                LightSample computed;
                if (!pre) {
                    const Vec2 u = light.uses_random_sample ? sample_uniform2(here, dim) : Vec2(0.5f);
                    computed = light.light->sample(hit.point, i, u, m_options.convention);
                }
                const LightSample& s = pre ? pre->sample : computed;
                if (pre ? !pre->lit : !lights_surface(s, ng)) continue;
                const RGB f = material.direct(t, wo_local, frame.to_local(s.wi), m_options.convention);
                if (f.is_black()) continue;
                L += f * s.arriving * transmittance(hit, s, stats, pre ? pre->shadow : kNotTraced);
            }
        }
    }

    if (depth < m_options.max_depth && !(t.kr.is_black() && t.kt.is_black())) {
        RGB kr = t.kr, kt = t.kt;
        const float eta =
            entering ? material.ior_outside() / material.ior_inside() : material.ior_inside() / material.ior_outside();
        // One transmitted cosine for both: dot(wo, ns) is exactly cos_i, and its clamp changes transmitted_cos2
        // only when it is negative (then fresnel_dielectric works it out itself).
        const float cos_i = -glm::dot(d, ns);
        const float cos2_t = transmitted_cos2(cos_i, eta);
        const std::optional<Vec3> refracted = refract_given(d, ns, eta, cos_i, cos2_t);
        if (material.fresnel()) {
            const float f = cos_i >= 0.0f ? fresnel_dielectric_given(std::min(cos_i, 1.0f), cos2_t, eta)
                                          : fresnel_dielectric(glm::dot(wo, ns), eta);
            kr *= f;
            kt *= 1.0f - f;
        }
        if (!refracted) {  // total internal reflection: what would have been transmitted is reflected
            kr += kt;
            kt = RGB{};
        }
        const float wr = weight * kr.max_component();
        if (wr > m_options.min_weight) {
            ++stats.reflected;
            const Vec3 r = keep_on_side(reflect(d, ns), ng, 1.0f);
            L += kr * trace(spawn_ray(hit, r), key, depth + 1, crossings, wr, stats);
        }
        const float wt = weight * kt.max_component();
        if (refracted && wt > m_options.min_weight) {
            ++stats.refracted;
            const Vec3 dir = keep_on_side(glm::normalize(*refracted), ng, -1.0f);
            L += kt * trace(spawn_ray(hit, dir), key, depth + 1, crossings, wt, stats);
        }
    }

    // A ray arriving from inside an absorbing medium has crossed it from where it started.
    if (!entering && !material.absorption().is_black()) L *= exp_rgb(material.absorption() * (-hit.t * dlen));
    return t.opacity < 1.0f ? t.opacity * L + behind : L;
}

}  // namespace rtlab
