#pragma once
// What the photon-mapping integrators (photon, sppm) share with each other: the camera path's walk to its first
// diffuse vertex and the direct light there, built on the path tracer's own pieces (rtlab/shading/path_vertex.hpp)
// so that their direct light, emission and MIS weights are the path tracer's. Private to the render library.
#include <rtlab/core/sample_stream.hpp>
#include <rtlab/shading/light_set.hpp>
#include <rtlab/shading/path.hpp>
#include <rtlab/shading/path_vertex.hpp>
#include <rtlab/shading/scene_query.hpp>

#include <cstdint>
#include <optional>

namespace rtlab::detail {

/// \brief Where a camera path meets its first diffuse scattering: the photon integrators' gather point (SPPM's
/// visible point).
struct GatherPoint {
    PathVertex v;
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
    PathVertex v;
};

/// Whether a vertex whose non-delta lobe was drawn is a gather point: when its material has a diffuse term
/// (SurfaceTerms::diffuse: Lambert's albedo, Phong's and Cook-Torrance's kd, Ashikhmin-Shirley's rd). A glossy-only
/// one (rough glass, a metal, Phong without kd) is rather path traced, as pbrt's SPPM does: a density estimate with a
/// narrow lobe needs photons the estimate does not have. Either choice is unbiased: it depends on the vertex alone.
inline bool is_gather_vertex(const PathVertex& v) { return !v.terms.diffuse.is_black(); }

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
