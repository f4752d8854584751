#pragma once
/// \brief The path tracer's building blocks, shared with the photon mappers (rtlab::render's photon and sppm) so
/// that their direct light, emission and MIS weights are the path tracer's to the bit: a surface vertex in its
/// shading frame, the light a ray brings from what it met, and next-event estimation.
#include <rtlab/core/frame.hpp>
#include <rtlab/shading/light_set.hpp>
#include <rtlab/shading/path.hpp>
#include <rtlab/shading/scene_query.hpp>

#include <cstdint>

namespace rtlab {

/// \brief A surface point a ray found, with what shading it needs.
struct PathVertex {
    SurfaceHit hit;
    SurfaceInfo info;
    SurfaceTerms terms;
    Frame frame;
    Vec3 wo_local{0.0f, 0.0f, 1.0f};    ///< towards the ray's origin, in the shading frame
    Vec3 wo{0.0f, 0.0f, 1.0f};          ///< the same in world space
    Normal3 outward{0.0f, 0.0f, 1.0f};  ///< geometric, after the reversed flag
    RGB absorbed{1.0f};                 ///< Beer-Lambert over the ray's stretch when it left an absorbing medium
};

/// Veach's power heuristic (beta 2) for the strategy of density a against one of density b.
inline float power_heuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

/// The pair of the camera sample's stream for decision j (0: light choice and roulette, 1: point on the light,
/// 2: BSDF direction, 3: lobe choice) at scattering vertex `bounce` (0 at the camera ray's hit): PathIntegrator's
/// numbering.
inline std::uint32_t path_pair(std::uint32_t bounce, std::uint32_t j) {
    return kFirstIntegratorPair + bounce * PathIntegrator::kPairsPerBounce + j;
}

/// The closest surface along `ray` as a vertex; false when the ray escapes (or is degenerate).
bool find_path_vertex(const SceneQuery& scene, const Ray& ray, PathVertex& v);

/// The emitted radiance `ray` brings from what it met (v when found, else the environment: PathOptions::environment
/// looked up, or the lights' environment), weighed against light sampling from `from` by the power heuristic
/// unless `specular` (the camera ray, or a delta lobe before: no other strategy finds that light).
RGB emitted_radiance(const LightSet& lights, const PathOptions& options, const Ray& ray, bool found,
                     const PathVertex& v, const Point3& from, float bsdf_pdf, bool specular);

/// Next-event estimation at v with the power heuristic against v's BSDF sampling: u_choice picks the light, u_light
/// the point on it; the shadow ray crosses cut-outs (opacity < 1) up to options.max_crossings times.
RGB sample_direct_light(const SceneQuery& scene, const LightSet& lights, const PathOptions& options,
                        const PathVertex& v, float u_choice, const Vec2& u_light, RayStats& stats);

}  // namespace rtlab
