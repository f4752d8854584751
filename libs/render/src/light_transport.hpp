#pragma once
// What the photon-mapping integrators (photon, sppm) share with each other, written after PathIntegrator's private
// parts (libs/shading/src/path.cpp) so that their direct light, emission and MIS weights are the path tracer's:
// a surface vertex with its shading frame, emitted light met by a ray (with its MIS weight), and next-event
// estimation. Private to the render library.
#include <rtlab/core/frame.hpp>
#include <rtlab/core/sample_stream.hpp>
#include <rtlab/shading/light_set.hpp>
#include <rtlab/shading/path.hpp>
#include <rtlab/shading/scene_query.hpp>

#include <cstdint>
#include <optional>

namespace rtlab::detail {

/// A surface point a ray found, with what shading it needs (PathIntegrator's Vertex).
struct SurfaceVertex {
    SurfaceHit hit;
    SurfaceInfo info;
    SurfaceTerms terms;
    Frame frame;
    Vec3 wo_local{0.0f, 0.0f, 1.0f};    // towards the ray's origin, in the shading frame
    Vec3 wo{0.0f, 0.0f, 1.0f};          // the same in world space
    Normal3 outward{0.0f, 0.0f, 1.0f};  // geometric, after the reversed flag
    RGB absorbed{1.0f};                 // Beer-Lambert over the ray's stretch when it left an absorbing medium
};

/// Veach's power heuristic (beta 2).
inline float power_heuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

/// The pair of the camera stream for decision j (0: light choice, 1: light point, 2: BSDF direction, 3: lobe choice)
/// at scattering vertex `bounce` (0 at the camera ray's hit): PathIntegrator's numbering.
inline std::uint32_t bounce_pair(std::uint32_t bounce, std::uint32_t j) {
    return kFirstIntegratorPair + bounce * PathIntegrator::kPairsPerBounce + j;
}

/// The closest surface along `ray`, false when it escapes (or the ray is degenerate).
bool find_vertex(const SceneQuery& scene, const Ray& ray, SurfaceVertex& v);

/// Emitted radiance the ray brings from what it met (v when found, else the environment), weighed against light
/// sampling from `from` by the power heuristic unless `specular` (the previous bounce was a delta lobe or the camera):
/// PathIntegrator's `arrived`.
RGB emitted_radiance(const LightSet& lights, const PathOptions& options, const Ray& ray, bool found,
                     const SurfaceVertex& v, const Point3& from, float bsdf_pdf, bool specular);

/// Next-event estimation at v with MIS against BSDF sampling (PathIntegrator's sample_light): u_choice picks the
/// light, u_light the point on it.
RGB sample_direct_light(const SceneQuery& scene, const LightSet& lights, const PathOptions& options,
                        const SurfaceVertex& v, float u_choice, const Vec2& u_light, RayStats& stats);

/// \brief Where a camera path meets its first diffuse scattering: the photon integrators' gather point (SPPM's
/// visible point).
struct GatherPoint {
    SurfaceVertex v;
    RGB beta;             // the camera path's throughput up to v, v's absorption included
    float chance = 1.0f;  // Material::non_delta_chance at v: a density estimate at v is weighed by beta / chance
    BsdfSample sample;    // the non-delta sample drawn at v (its value already carries the 1 / chance)
    /// v's scattering index (0 at the camera ray's hit): v with a photon of b bounces makes a path of bounce + 1 + b
    /// scattering events, allowed up to PathOptions::max_depth.
    std::uint32_t bounce = 0;
    float distance = 0.0f;  // path length from the walk's start to v
    RGB weight() const { return beta * (1.0f / chance); }
};

/// \brief The surface a ray found (a gather point's own BSDF sample: a final gather's first ray).
struct GatherHit {
    Ray ray;
    bool found = false;
    SurfaceVertex v;
};

/// Whether a vertex whose non-delta lobe was drawn is a gather point: when its material has a diffuse term
/// (SurfaceTerms::diffuse: Lambert's albedo, Phong's and Cook-Torrance's kd, Ashikhmin-Shirley's rd). A glossy-only
/// one (rough glass, a metal, Phong without kd) is rather path traced, as pbrt's SPPM does: a density estimate with a
/// narrow lobe needs photons the estimate does not have. Either choice is unbiased: it depends on the vertex alone.
inline bool is_gather_vertex(const SurfaceVertex& v) { return !v.terms.diffuse.is_black(); }

/// \brief Where a walk starts.
struct WalkStart {
    Ray ray;
    RGB beta{1.0f};
    std::uint32_t bounce = 0;  ///< the scattering index of the first vertex the ray finds
    /// The camera's walk counts the light it meets on the way: emission, and next-event estimation at the vertices it
    /// path traces. A final gather ray's walk counts none (the caustic map holds the light that reaches the gather
    /// point through pass-through vertices alone) and only finds the next gather point.
    bool camera = true;
    const GatherHit* first = nullptr;  ///< the ray's hit when already found (ray and found as traced)
};

/// Follows a ray through the vertices it does not gather at, to the first gather point: at each vertex it draws
/// the material's mixture (stream pairs of PathIntegrator's numbering at the vertex's bounce). A delta lobe is
/// followed. A non-delta lobe at a gather vertex (is_gather_vertex) makes `gp`; the draw decides between the vertex's
/// two parts, the non-delta part estimated at gp with weight beta / chance and the delta lobes followed, each chosen
/// with its probability, so together they are unbiased. A non-delta lobe elsewhere (glossy) is followed too, path
/// traced: on the camera's walk with next-event estimation there (beta / chance) and the emission the sample meets
/// weighed by MIS. The scattering events a walk passes through (delta lobes, and non-delta ones at vertices that are
/// not gather vertices) are the pass-through events P of PhotonPath. Returns the light counted on the way; gp is left
/// empty when the walk ends first (escape, black, max_depth).
RGB walk_to_gather_point(const SceneQuery& scene, const LightSet& lights, const PathOptions& options,
                         const WalkStart& start, const SampleStream& stream, RayStats& stats,
                         std::optional<GatherPoint>& gp);

/// Direct light at a gather point: next-event estimation (weighed by beta / chance) plus, from gp.sample's ray, the
/// emission it meets weighed by MIS (by beta sample.value): PathIntegrator's two strategies for one bounce. `hit` gets
/// what that ray found.
RGB direct_at_gather_point(const SceneQuery& scene, const LightSet& lights, const PathOptions& options,
                           const GatherPoint& gp, const SampleStream& stream, RayStats& stats, GatherHit& hit);

}  // namespace rtlab::detail
