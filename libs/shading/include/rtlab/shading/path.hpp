#pragma once
/// \brief The sampling integrators: `direct` (emitted light plus one bounce of direct light) and `path` (a path
/// tracer), both combining light sampling and BSDF sampling by multiple importance sampling (power heuristic).
#include <rtlab/core/sample_stream.hpp>
#include <rtlab/shading/light_set.hpp>
#include <rtlab/shading/scene_query.hpp>
#include <rtlab/shading/whitted.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>

namespace rtlab {

/// \brief The integrators a render can choose by name: photon (photon mapping) and sppm (stochastic progressive
/// photon mapping) are rtlab::render's (rtlab/render/photon_integrator.hpp, sppm.hpp).
enum class IntegratorKind { whitted, direct, path, photon, sppm };
/// "whitted", "direct", "path", "photon" or "sppm"; nullopt for another word.
std::optional<IntegratorKind> parse_integrator(std::string_view name);
std::string_view integrator_name(IntegratorKind kind);

/// \brief Settings of the sampling integrators (direct reads only max_crossings and environment).
struct PathOptions {
    /// Bounces as pbrt counts them: 0 = only light seen directly, 1 = direct light (what `direct` computes).
    int max_depth = 8;
    /// Russian roulette may end a path from this bounce on (bounces counted from 0 at the camera's hit)...
    int roulette_depth = 3;
    bool roulette = true;
    /// ...surviving with min(max_survival, throughput's largest channel), capped below 1 so a path of
    /// throughput 1 (a furnace) still ends; the survivor's throughput is divided by it.
    float max_survival = 0.95f;
    int max_crossings = 64;  ///< cut-outs (opacity < 1) a shadow ray crosses at most
    /// Looked up with the direction for rays that escape, without light sampling (BSDF sampling alone finds
    /// it, so it stays unbiased); an environment light (uniform or a map) is instead the LightSet's environment,
    /// sampled and weighed by MIS.
    std::shared_ptr<const Texture> environment;
};

/// \brief direct and path over a SceneQuery and a LightSet (both must outlive it).
///
/// Numbers: at bounce b (0 at the camera ray's hit) the integrator uses pairs kFirstIntegratorPair + 4 b + j of
/// the camera sample's stream: j = 0 (light choice, Russian roulette), 1 (point on the light), 2 (BSDF direction),
/// 3 (BSDF lobe choice in x). `direct` draws bounce 0's, so `path` at max_depth 1 gives the same bytes.
/// Emission leaves a shape's front face (outward normal after the reversed flag) unless the material is
/// emission_two_sided; a shape with textured emission is not sampled as a light (only BSDF sampling finds it).
/// Its building blocks (vertex, emission with its MIS weight, next-event estimation) are rtlab/shading/path_vertex.hpp,
/// which the photon mappers share.
class PathIntegrator {
public:
    static constexpr std::uint32_t kPairsPerBounce = 4;

    /// Throws rtlab::Error for max_depth < 0, roulette_depth < 0 or max_survival outside (0, 1).
    PathIntegrator(const SceneQuery& scene, const LightSet& lights, PathOptions options = {});

    /// Radiance along -ray.direction at ray.origin by a path of up to max_depth bounces.
    RGB path(const Ray& ray, const SampleStream& stream, RayStats& stats) const;
    /// Emitted light plus direct light at the first hit: path() at max_depth 1, written on its own.
    RGB direct(const Ray& ray, const SampleStream& stream, RayStats& stats) const;

    const PathOptions& options() const { return m_options; }

private:
    const SceneQuery& m_scene;
    const LightSet& m_lights;
    PathOptions m_options;
};

}  // namespace rtlab
