#include "shading_frame.hpp"

#include <rtlab/geometry/spawn.hpp>
#include <rtlab/shading/path_vertex.hpp>

#include <cmath>

namespace rtlab {

namespace {

// What a shadow ray to the light sample lets through. Only cut-outs let it through: transmission by kt or a
// dielectric is a delta lobe, which no light sample can meet (BSDF sampling carries that light).
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

bool find_path_vertex(const SceneQuery& scene, const Ray& ray, PathVertex& v) {
    const float dlen = glm::length(ray.direction);
    if (!(dlen > 0.0f) || !std::isfinite(dlen)) return false;
    if (!scene.intersect_surface(ray, v.hit, v.info)) return false;
    const Vec3 d = ray.direction / dlen;
    const bool reversed = v.info.flags.reversed;
    v.outward = reversed ? -v.hit.geometric_normal : v.hit.geometric_normal;
    Normal3 ns = reversed ? -v.hit.shading_normal : v.hit.shading_normal;
    // A shading normal that puts the viewer on the other side than the true surface does gives way to it.
    if (!(glm::dot(ns, d) * glm::dot(v.outward, d) > 0.0f) || !is_finite(ns)) ns = v.outward;
    v.frame = shading_detail::shading_frame(ns, v.hit.tangent);
    v.wo = -d;
    v.wo_local = v.frame.to_local(-d);
    TextureLookup q;
    q.uv = v.hit.uv;
    q.point = v.hit.object_point;
    q.direction = d;
    v.terms = v.info.material->terms(q);
    v.absorbed = RGB(1.0f);
    const RGB& sigma = v.info.material->absorption();
    if (!sigma.is_black() && glm::dot(d, v.outward) > 0.0f)
        v.absorbed = shading_detail::exp_rgb(sigma * (-v.hit.t * dlen));
    return true;
}

RGB emitted_radiance(const LightSet& lights, const PathOptions& options, const Ray& ray, bool found,
                     const PathVertex& v, const Point3& from, float bsdf_pdf, bool specular) {
    if (!found) {
        if (options.environment) {
            TextureLookup q;
            q.direction = ray.direction;
            return options.environment->eval(q);
        }
        const LightSet::Entry* env = lights.environment();
        if (!env) return {};
        const RGB le = lights.environment_emitter()->radiance(ray.direction);
        if (specular || le.is_black()) return le;
        const Vec3 wi = glm::normalize(ray.direction);
        const float light_pdf = env->probability * env->emitter->pdf_li(from, wi, from, v.outward);
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
                        const PathVertex& v, float u_choice, const Vec2& u_light, RayStats& stats) {
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

}  // namespace rtlab
