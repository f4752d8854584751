#include <rtlab/core/error.hpp>
#include <rtlab/geometry/spawn.hpp>
#include <rtlab/shading/path.hpp>
#include <rtlab/shading/path_vertex.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

std::optional<IntegratorKind> parse_integrator(std::string_view name) {
    if (name == "whitted") return IntegratorKind::whitted;
    if (name == "direct") return IntegratorKind::direct;
    if (name == "path") return IntegratorKind::path;
    if (name == "photon") return IntegratorKind::photon;
    if (name == "sppm") return IntegratorKind::sppm;
    return std::nullopt;
}

std::string_view integrator_name(IntegratorKind kind) {
    switch (kind) {
        case IntegratorKind::whitted:
            return "whitted";
        case IntegratorKind::direct:
            return "direct";
        case IntegratorKind::path:
            return "path";
        case IntegratorKind::photon:
            return "photon";
        case IntegratorKind::sppm:
            return "sppm";
    }
    return "whitted";
}

PathIntegrator::PathIntegrator(const SceneQuery& scene, const LightSet& lights, PathOptions options)
    : m_scene(scene), m_lights(lights), m_options(std::move(options)) {
    if (m_options.max_depth < 0) throw Error("path: max_depth must be >= 0");
    if (m_options.roulette_depth < 0) throw Error("path: roulette_depth must be >= 0");
    if (!(m_options.max_survival > 0.0f && m_options.max_survival < 1.0f))
        throw Error("path: max_survival must be in (0, 1)");
}

RGB PathIntegrator::path(const Ray& camera_ray, const SampleStream& stream, RayStats& stats) const {
    RGB L, beta(1.0f);
    bool specular = true;  // the camera ray: what it sees directly has no other strategy
    float bsdf_pdf = 0.0f;
    Point3 from = camera_ray.origin;
    Ray ray = camera_ray;
    for (int depth = 0;; ++depth) {
        PathVertex v;
        const bool found = find_path_vertex(m_scene, ray, v);
        if (found) beta *= v.absorbed;
        L += beta * emitted_radiance(m_lights, m_options, ray, found, v, from, bsdf_pdf, specular);
        if (!found || depth >= m_options.max_depth) break;
        const auto bounce = static_cast<std::uint32_t>(depth);
        // Pair 0 serves the light choice (x) and Russian roulette (y): drawn once, and only when one of them reads
        // it (a pair costs about as much as a shading normal); so is pair 3's lobe choice. A number left undrawn is
        // one nothing reads, so the image is the same bits.
        const bool roulette =
            m_options.roulette && depth + 1 >= m_options.roulette_depth && depth + 1 < m_options.max_depth;
        const Material& material = *v.info.material;
        const Vec2 u_choice = roulette || (m_lights.choice_uses_u() && material.reflects_direct_light())
                                  ? stream.get2d(path_pair(bounce, 0))
                                  : Vec2(0.0f);
        const Vec2 u_light = material.reflects_direct_light() ? stream.get2d(path_pair(bounce, 1)) : Vec2(0.0f);
        L += beta * sample_direct_light(m_scene, m_lights, m_options, v, u_choice.x, u_light, stats);
        const float u_lobe = material.sample_uses_choice(v.terms) ? stream.get2d(path_pair(bounce, 3)).x : 0.0f;
        const std::optional<BsdfSample> bs =
            material.sample(v.terms, v.wo_local, u_lobe, stream.get2d(path_pair(bounce, 2)), TransportMode::radiance);
        if (!bs) break;
        beta *= bs->value;
        if (beta.is_black()) break;
        specular = (bs->flags & kLobeSpecular) != 0;
        bsdf_pdf = bs->pdf;
        from = v.hit.point;
        // Roulette before a bounce that would add more than emission: one at max_depth would only end paths
        // that have a single emitted term left to add.
        if (roulette) {
            const float q = std::min(m_options.max_survival, beta.max_component());
            if (!(u_choice.y < q)) break;
            beta *= 1.0f / q;
        }
        const Vec3 wi = v.frame.to_world(bs->wi);
        if (bs->flags & kLobeTransmission)
            ++stats.refracted;
        else
            ++stats.reflected;
        ray = spawn_ray(v.hit, wi);
    }
    return L;
}

RGB PathIntegrator::direct(const Ray& camera_ray, const SampleStream& stream, RayStats& stats) const {
    RGB beta(1.0f);
    PathVertex v;
    if (!find_path_vertex(m_scene, camera_ray, v))
        return emitted_radiance(m_lights, m_options, camera_ray, false, v, camera_ray.origin, 0.0f, true);
    beta *= v.absorbed;
    RGB L = beta * emitted_radiance(m_lights, m_options, camera_ray, true, v, camera_ray.origin, 0.0f, true);
    if (m_options.max_depth < 1) return L;
    L += beta * sample_direct_light(m_scene, m_lights, m_options, v, stream.get2d(path_pair(0, 0)).x,
                                    stream.get2d(path_pair(0, 1)), stats);
    const std::optional<BsdfSample> bs = v.info.material->sample(
        v.terms, v.wo_local, stream.get2d(path_pair(0, 3)).x, stream.get2d(path_pair(0, 2)), TransportMode::radiance);
    if (!bs) return L;
    beta *= bs->value;
    if (beta.is_black()) return L;
    if (bs->flags & kLobeTransmission)
        ++stats.refracted;
    else
        ++stats.reflected;
    const Ray ray = spawn_ray(v.hit, v.frame.to_world(bs->wi));
    PathVertex w;
    const bool found = find_path_vertex(m_scene, ray, w);
    if (found) beta *= w.absorbed;
    return L + beta * emitted_radiance(m_lights, m_options, ray, found, w, v.hit.point, bs->pdf,
                                       (bs->flags & kLobeSpecular) != 0);
}

}  // namespace rtlab
