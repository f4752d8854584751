#include "light_transport.hpp"

#include <rtlab/geometry/spawn.hpp>

namespace rtlab::detail {

RGB walk_to_gather_point(const SceneQuery& scene, const LightSet& lights, const PathOptions& options,
                         const WalkStart& start, const SampleStream& stream, RayStats& stats,
                         std::optional<GatherPoint>& gp) {
    gp.reset();
    RGB L, beta = start.beta;
    Ray ray = start.ray;
    const bool counting = start.camera;
    bool specular = true;  // the start or a delta lobe before: emission met has no other strategy
    float bsdf_pdf = 0.0f;
    Point3 from = ray.origin;
    float distance = 0.0f;
    for (std::uint32_t bounce = start.bounce;; ++bounce) {
        PathVertex v;
        bool found = false;
        if (start.first && bounce == start.bounce) {
            found = start.first->found;
            if (found) v = start.first->v;
        } else {
            found = find_path_vertex(scene, ray, v);
        }
        if (found) beta *= v.absorbed;
        if (counting) L += beta * emitted_radiance(lights, options, ray, found, v, from, bsdf_pdf, specular);
        if (!found || static_cast<long>(bounce) >= static_cast<long>(options.max_depth)) return L;
        distance += v.hit.t * glm::length(ray.direction);
        const Material& material = *v.info.material;
        const std::optional<BsdfSample> s =
            material.sample(v.terms, v.wo_local, stream.get2d(path_pair(bounce, 3)).x,
                            stream.get2d(path_pair(bounce, 2)), TransportMode::radiance);
        if (!s) return L;
        if (!(s->flags & kLobeSpecular)) {
            const float chance = material.non_delta_chance(v.terms, v.wo_local);
            if (!(chance > 0.0f)) return L;
            if (is_gather_vertex(v)) {
                gp = GatherPoint{v, beta, chance, *s, bounce, distance};
                return L;
            }
            if (counting)
                L += beta * (1.0f / chance) *
                     sample_direct_light(scene, lights, options, v, stream.get2d(path_pair(bounce, 0)).x,
                                         stream.get2d(path_pair(bounce, 1)), stats);
        }
        beta *= s->value;
        if (beta.is_black()) return L;
        specular = (s->flags & kLobeSpecular) != 0;
        bsdf_pdf = s->pdf;
        from = v.hit.point;
        if (s->flags & kLobeTransmission)
            ++stats.refracted;
        else
            ++stats.reflected;
        ray = spawn_ray(v.hit, v.frame.to_world(s->wi));
    }
}

RGB direct_at_gather_point(const SceneQuery& scene, const LightSet& lights, const PathOptions& options,
                           const GatherPoint& gp, const SampleStream& stream, RayStats& stats, GatherHit& hit) {
    const PathVertex& v = gp.v;
    RGB L = gp.weight() * sample_direct_light(scene, lights, options, v, stream.get2d(path_pair(gp.bounce, 0)).x,
                                              stream.get2d(path_pair(gp.bounce, 1)), stats);
    if (gp.sample.flags & kLobeTransmission)
        ++stats.refracted;
    else
        ++stats.reflected;
    hit.ray = spawn_ray(v.hit, v.frame.to_world(gp.sample.wi));
    hit.found = find_path_vertex(scene, hit.ray, hit.v);
    RGB through = gp.beta * gp.sample.value;
    if (hit.found) through *= hit.v.absorbed;
    L += through * emitted_radiance(lights, options, hit.ray, hit.found, hit.v, v.hit.point, gp.sample.pdf, false);
    return L;
}

}  // namespace rtlab::detail
