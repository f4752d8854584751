#include "light_transport.hpp"

#include <rtlab/geometry/spawn.hpp>

#include <cmath>

namespace rtlab::detail {

namespace {

RGB exp_rgb(const RGB& c) { return {std::exp(c.r), std::exp(c.g), std::exp(c.b)}; }

// The shading frame: the shading normal, and the surface tangent as local +x (anisotropic models need it).
Frame shading_frame(const Normal3& n, const Vec3& tangent) {
    Vec3 s = tangent - glm::dot(tangent, n) * n;
    const float len = glm::length(s);
    if (!(len > 1e-6f) || !std::isfinite(len)) return Frame::from_normal(n);
    s /= len;
    return Frame{s, glm::cross(n, s), n};
}

// What a shadow ray to the light sample lets through: only cut-outs (opacity < 1) pass light, as in path.cpp.
RGB visibility(const SceneQuery& scene, int max_crossings, const SurfaceHit& from, const EmitterSample& s,
               RayStats& stats) {
    auto segment = [&s](const SurfaceHit& h) {
        return s.at_infinity ? spawn_ray(h, s.wi) : spawn_ray_to(h, s.position);
    };
    Ray ray = segment(from);
    ++stats.shadow;
    RGB through(1.0f);
    for (int i = 0; i < max_crossings; ++i) {
        SurfaceHit h;
        SurfaceInfo info;
        const ShadowHit met = scene.shadow(ray, i == 0, h, info);
        if (met == ShadowHit::opaque) return {};
        if (met == ShadowHit::clear) return through;
        TextureLookup q;
        q.uv = h.uv;
        q.point = h.object_point;
        q.direction = ray.direction;
        through *= 1.0f - info.material->terms(q).opacity;
        if (through.is_black()) return {};
        ray = segment(h);
        ++stats.shadow;
    }
    return {};
}

}  // namespace

bool find_vertex(const SceneQuery& scene, const Ray& ray, SurfaceVertex& v) {
    const float dlen = glm::length(ray.direction);
    if (!(dlen > 0.0f) || !std::isfinite(dlen)) return false;
    if (!scene.intersect_surface(ray, v.hit, v.info)) return false;
    const Vec3 d = ray.direction / dlen;
    v.outward = v.info.flags.reversed ? -v.hit.geometric_normal : v.hit.geometric_normal;
    Normal3 ns = v.info.flags.reversed ? -v.hit.shading_normal : v.hit.shading_normal;
    // A shading normal that puts the viewer on the other side than the true surface does gives way to it.
    if (!(glm::dot(ns, d) * glm::dot(v.outward, d) > 0.0f) || !is_finite(ns)) ns = v.outward;
    v.frame = shading_frame(ns, v.hit.tangent);
    v.wo = -d;
    v.wo_local = v.frame.to_local(-d);
    TextureLookup q;
    q.uv = v.hit.uv;
    q.point = v.hit.object_point;
    q.direction = d;
    v.terms = v.info.material->terms(q);
    v.absorbed = RGB(1.0f);
    const RGB& sigma = v.info.material->absorption();
    if (!sigma.is_black() && glm::dot(d, v.outward) > 0.0f) v.absorbed = exp_rgb(sigma * (-v.hit.t * dlen));
    return true;
}

RGB emitted_radiance(const LightSet& lights, const PathOptions& options, const Ray& ray, bool found,
                     const SurfaceVertex& v, const Point3& from, float bsdf_pdf, bool specular) {
    if (!found) {
        if (options.environment) {
            TextureLookup q;
            q.direction = ray.direction;
            return options.environment->eval(q);
        }
        const LightSet::Entry* env = lights.environment();
        if (!env) return {};
        const RGB& le = lights.environment_emitter()->radiance();
        if (specular) return le;
        const float light_pdf = env->probability * env->emitter->pdf_li(from, ray.direction, from, v.outward);
        return le * power_heuristic(bsdf_pdf, light_pdf);
    }
    const RGB& le = v.terms.emission;
    if (le.is_black()) return {};
    if (!v.info.material->emission_two_sided() && !(glm::dot(ray.direction, v.outward) < 0.0f)) return {};
    const LightSet::Entry* light = lights.for_shape(v.hit.shape);
    if (specular || !light) return le;
    const Vec3 wi = glm::normalize(ray.direction);
    const float light_pdf = light->probability * light->emitter->pdf_li(from, wi, v.hit.point, v.outward);
    return le * power_heuristic(bsdf_pdf, light_pdf);
}

RGB sample_direct_light(const SceneQuery& scene, const LightSet& lights, const PathOptions& options,
                        const SurfaceVertex& v, float u_choice, const Vec2& u_light, RayStats& stats) {
    const Material& material = *v.info.material;
    if (!material.reflects_direct_light()) return {};
    const LightSet::Entry* light = lights.choose(u_choice);
    if (!light) return {};
    const std::optional<EmitterSample> s = light->emitter->sample_li(v.hit.point, u_light);
    if (!s) return {};
    const Vec3 wi = v.frame.to_local(s->wi);
    const RGB f = material.eval(v.terms, v.wo_local, wi, TransportMode::radiance);
    if (f.is_black()) return {};
    const RGB tr = visibility(scene, options.max_crossings, v.hit, *s, stats);
    if (tr.is_black()) return {};
    const RGB contribution = f * s->radiance * tr * std::abs(wi.z);
    if (light->emitter->is_delta()) return contribution * (1.0f / light->probability);
    const float light_pdf = light->probability * s->pdf;
    const float bsdf_pdf = material.pdf(v.terms, v.wo_local, wi, TransportMode::radiance);
    return contribution * (power_heuristic(light_pdf, bsdf_pdf) / light_pdf);
}

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
        SurfaceVertex v;
        bool found = false;
        if (start.first && bounce == start.bounce) {
            found = start.first->found;
            if (found) v = start.first->v;
        } else {
            found = find_vertex(scene, ray, v);
        }
        if (found) beta *= v.absorbed;
        if (counting) L += beta * emitted_radiance(lights, options, ray, found, v, from, bsdf_pdf, specular);
        if (!found || static_cast<long>(bounce) >= static_cast<long>(options.max_depth)) return L;
        distance += v.hit.t * glm::length(ray.direction);
        const Material& material = *v.info.material;
        const std::optional<BsdfSample> s =
            material.sample(v.terms, v.wo_local, stream.get2d(bounce_pair(bounce, 3)).x,
                            stream.get2d(bounce_pair(bounce, 2)), TransportMode::radiance);
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
                     sample_direct_light(scene, lights, options, v, stream.get2d(bounce_pair(bounce, 0)).x,
                                         stream.get2d(bounce_pair(bounce, 1)), stats);
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
    const SurfaceVertex& v = gp.v;
    RGB L = gp.weight() * sample_direct_light(scene, lights, options, v, stream.get2d(bounce_pair(gp.bounce, 0)).x,
                                              stream.get2d(bounce_pair(gp.bounce, 1)), stats);
    if (gp.sample.flags & kLobeTransmission)
        ++stats.refracted;
    else
        ++stats.reflected;
    hit.ray = spawn_ray(v.hit, v.frame.to_world(gp.sample.wi));
    hit.found = find_vertex(scene, hit.ray, hit.v);
    RGB through = gp.beta * gp.sample.value;
    if (hit.found) through *= hit.v.absorbed;
    L += through * emitted_radiance(lights, options, hit.ray, hit.found, hit.v, v.hit.point, gp.sample.pdf, false);
    return L;
}

}  // namespace rtlab::detail
