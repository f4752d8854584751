#include "shading_frame.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/geometry/spawn.hpp>
#include <rtlab/shading/path.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

namespace {

using shading_detail::exp_rgb;
using shading_detail::shading_frame;

// Veach's power heuristic (beta 2) for the strategy of density a against one of density b.
float power_heuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

std::uint32_t bounce_pair(std::uint32_t bounce, std::uint32_t j) {
    return kFirstIntegratorPair + bounce * PathIntegrator::kPairsPerBounce + j;
}

}  // namespace

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

/// A surface point found by a ray, with what shading it needs.
struct PathIntegrator::Vertex {
    SurfaceHit hit;
    SurfaceInfo info;
    SurfaceTerms terms;
    Frame frame;
    Vec3 wo_local{0.0f, 0.0f, 1.0f};
    Normal3 outward{0.0f, 0.0f, 1.0f};  // geometric, after the reversed flag
    RGB absorbed{1.0f};                 // Beer-Lambert over the ray's stretch when it left an absorbing medium
};

PathIntegrator::PathIntegrator(const SceneQuery& scene, const LightSet& lights, PathOptions options)
    : m_scene(scene), m_lights(lights), m_options(std::move(options)) {
    if (m_options.max_depth < 0) throw Error("path: max_depth must be >= 0");
    if (m_options.roulette_depth < 0) throw Error("path: roulette_depth must be >= 0");
    if (!(m_options.max_survival > 0.0f && m_options.max_survival < 1.0f))
        throw Error("path: max_survival must be in (0, 1)");
}

bool PathIntegrator::find(const Ray& ray, Vertex& v) const {
    const float dlen = glm::length(ray.direction);
    if (!(dlen > 0.0f) || !std::isfinite(dlen)) return false;
    if (!m_scene.intersect_surface(ray, v.hit, v.info)) return false;
    const Vec3 d = ray.direction / dlen;
    const bool reversed = v.info.flags.reversed;
    v.outward = reversed ? -v.hit.geometric_normal : v.hit.geometric_normal;
    Normal3 ns = reversed ? -v.hit.shading_normal : v.hit.shading_normal;
    // A shading normal that puts the viewer on the other side than the true surface does gives way to it.
    if (!(glm::dot(ns, d) * glm::dot(v.outward, d) > 0.0f) || !is_finite(ns)) ns = v.outward;
    v.frame = shading_frame(ns, v.hit.tangent);
    v.wo_local = v.frame.to_local(-d);
    TextureLookup q;
    q.uv = v.hit.uv;
    q.point = v.hit.object_point;
    q.direction = d;
    v.terms = v.info.material->terms(q);
    const RGB& sigma = v.info.material->absorption();
    if (!sigma.is_black() && glm::dot(d, v.outward) > 0.0f) v.absorbed = exp_rgb(sigma * (-v.hit.t * dlen));
    return true;
}

RGB PathIntegrator::arrived(const Ray& ray, bool found, const Vertex& v, const Point3& from, float bsdf_pdf,
                            bool specular) const {
    if (!found) {
        if (m_options.environment) {
            TextureLookup q;
            q.direction = ray.direction;
            return m_options.environment->eval(q);
        }
        const LightSet::Entry* env = m_lights.environment();
        if (!env) return {};
        const RGB& le = m_lights.environment_emitter()->radiance();
        if (specular) return le;
        const float light_pdf = env->probability * env->emitter->pdf_li(from, ray.direction, from, v.outward);
        return le * power_heuristic(bsdf_pdf, light_pdf);
    }
    const RGB& le = v.terms.emission;
    if (le.is_black()) return {};
    if (!v.info.material->emission_two_sided() && !(glm::dot(ray.direction, v.outward) < 0.0f)) return {};
    const LightSet::Entry* light = m_lights.for_shape(v.hit.shape);
    if (specular || !light) return le;
    const Vec3 wi = glm::normalize(ray.direction);
    const float light_pdf = light->probability * light->emitter->pdf_li(from, wi, v.hit.point, v.outward);
    return le * power_heuristic(bsdf_pdf, light_pdf);
}

RGB PathIntegrator::visibility(const SurfaceHit& from, const EmitterSample& s, RayStats& stats) const {
    auto segment = [&s](const SurfaceHit& h) {
        return s.at_infinity ? spawn_ray(h, s.wi) : spawn_ray_to(h, s.position);
    };
    Ray ray = segment(from);
    ++stats.shadow;
    RGB through(1.0f);
    // Only cut-outs let a shadow ray through: transmission by kt or a dielectric is a delta lobe, which no light
    // sample can meet (BSDF sampling carries that light).
    for (int i = 0; i < m_options.max_crossings; ++i) {
        SurfaceHit h;
        SurfaceInfo info;
        const ShadowHit met = m_scene.shadow(ray, i == 0, h, info);
        if (met == ShadowHit::opaque) return {};
        if (met == ShadowHit::clear) return through;
        TextureLookup q;
        q.uv = h.uv;
        q.point = h.object_point;
        q.direction = ray.direction;
        const float opacity = info.material->terms(q).opacity;
        through *= 1.0f - opacity;
        if (through.is_black()) return {};
        ray = segment(h);
        ++stats.shadow;
    }
    return {};
}

RGB PathIntegrator::sample_light(const Vertex& v, float u_choice, const SampleStream& stream, std::uint32_t bounce,
                                 RayStats& stats) const {
    const Material& material = *v.info.material;
    if (!material.reflects_direct_light()) return {};
    const LightSet::Entry* light = m_lights.choose(u_choice);
    if (!light) return {};
    const std::optional<EmitterSample> s = light->emitter->sample_li(v.hit.point, stream.get2d(bounce_pair(bounce, 1)));
    if (!s) return {};
    const Vec3 wi = v.frame.to_local(s->wi);
    const RGB f = material.eval(v.terms, v.wo_local, wi, TransportMode::radiance);
    if (f.is_black()) return {};
    const RGB tr = visibility(v.hit, *s, stats);
    if (tr.is_black()) return {};
    const RGB contribution = f * s->radiance * tr * std::abs(wi.z);
    if (light->emitter->is_delta()) return contribution * (1.0f / light->probability);
    const float light_pdf = light->probability * s->pdf;
    const float bsdf_pdf = material.pdf(v.terms, v.wo_local, wi, TransportMode::radiance);
    return contribution * (power_heuristic(light_pdf, bsdf_pdf) / light_pdf);
}

RGB PathIntegrator::path(const Ray& camera_ray, const SampleStream& stream, RayStats& stats) const {
    RGB L, beta(1.0f);
    bool specular = true;  // the camera ray: what it sees directly has no other strategy
    float bsdf_pdf = 0.0f;
    Point3 from = camera_ray.origin;
    Ray ray = camera_ray;
    for (int depth = 0;; ++depth) {
        Vertex v;
        const bool found = find(ray, v);
        if (found) beta *= v.absorbed;
        L += beta * arrived(ray, found, v, from, bsdf_pdf, specular);
        if (!found || depth >= m_options.max_depth) break;
        const auto bounce = static_cast<std::uint32_t>(depth);
        // Pair 0 serves the light choice (x) and Russian roulette (y): drawn once.
        const Vec2 u_choice = stream.get2d(bounce_pair(bounce, 0));
        L += beta * sample_light(v, u_choice.x, stream, bounce, stats);
        const std::optional<BsdfSample> bs =
            v.info.material->sample(v.terms, v.wo_local, stream.get2d(bounce_pair(bounce, 3)).x,
                                    stream.get2d(bounce_pair(bounce, 2)), TransportMode::radiance);
        if (!bs) break;
        beta *= bs->value;
        if (beta.is_black()) break;
        specular = (bs->flags & kLobeSpecular) != 0;
        bsdf_pdf = bs->pdf;
        from = v.hit.point;
        // Roulette before a bounce that would add more than emission: one at max_depth would only end paths
        // that have a single emitted term left to add.
        if (m_options.roulette && depth + 1 >= m_options.roulette_depth && depth + 1 < m_options.max_depth) {
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
    Vertex v;
    if (!find(camera_ray, v)) return arrived(camera_ray, false, v, camera_ray.origin, 0.0f, true);
    beta *= v.absorbed;
    RGB L = beta * arrived(camera_ray, true, v, camera_ray.origin, 0.0f, true);
    if (m_options.max_depth < 1) return L;
    L += beta * sample_light(v, stream.get2d(bounce_pair(0, 0)).x, stream, 0, stats);
    const std::optional<BsdfSample> bs =
        v.info.material->sample(v.terms, v.wo_local, stream.get2d(bounce_pair(0, 3)).x, stream.get2d(bounce_pair(0, 2)),
                                TransportMode::radiance);
    if (!bs) return L;
    beta *= bs->value;
    if (beta.is_black()) return L;
    if (bs->flags & kLobeTransmission)
        ++stats.refracted;
    else
        ++stats.reflected;
    const Ray ray = spawn_ray(v.hit, v.frame.to_world(bs->wi));
    Vertex w;
    const bool found = find(ray, w);
    if (found) beta *= w.absorbed;
    return L + beta * arrived(ray, found, w, v.hit.point, bs->pdf, (bs->flags & kLobeSpecular) != 0);
}

}  // namespace rtlab
