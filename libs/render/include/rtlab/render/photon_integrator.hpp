#pragma once
/// \brief Photon mapping (`photon`, Jensen 1996/2001): a caustic map and a global map shot once before the render,
/// read by every camera sample.
///
/// How the light reaching the eye is split, so that no light is counted twice. The scattering events are those of
/// PhotonPath: pass-through (P: a delta lobe drawn, or any lobe at a surface without a diffuse term, such as rough
/// glass or a metal) and diffuse (D: a non-delta lobe drawn at a surface with a diffuse term). A camera path goes on
/// through P events, adding the light it meets on the way as the path tracer does (emission, next-event estimation at
/// the glossy vertices it path traces, MIS between them), to its first D event, at the gather point x (a draw there
/// picks either the non-delta lobes, whose light x's estimates give, weighed by 1 / that draw's probability, or a
/// delta lobe, followed on). The light x reflects through its non-delta lobes, by the events of the light path before
/// x:
///   L x          direct light: next-event estimation at x, with MIS against x's own BSDF sample meeting a light
///                (PathIntegrator's two strategies);
///   L P+ x       caustics: the caustic map at x;
///   L .* D P* x  indirect light (at least one D event before x): with final gather (gather >= 1), rays from x by
///                its BSDF (the first is x's own sample) through P events, counting nothing on the way (the light
///                they would meet is direct or caustic light of x), to the next gather point y, where the global map
///                holds every photon (direct, caustic and indirect: all the light y reflects). Without final gather
///                (gather = 0) the global map holds only the indirect photons and is read at x itself.
/// Paths are limited to PathOptions::max_depth scattering events as the path tracer counts them: a photon of b
/// bounces counts at a vertex of scattering index c (0 at the camera ray's hit) when c + 1 + b <= max_depth.
///
/// Deterministic: the photons are the same for any thread count (trace_photons), the kd-tree's neighbours break
/// ties by index, and each camera sample is a pure function of its stream, so images are the same bytes for any
/// thread count. Biased (a fixed photon count) but consistent as the count grows with k / count -> 0; sppm is the
/// progressive, consistent variant (rtlab/render/sppm.hpp).
#include <rtlab/render/photon_map.hpp>
#include <rtlab/render/photon_tracer.hpp>
#include <rtlab/render/radiance_source.hpp>
#include <rtlab/shading/path.hpp>

#include <atomic>
#include <cstdint>

namespace rtlab {

struct PathVertex;
namespace detail {
struct WalkStart;
}  // namespace detail

/// \brief Settings of photon and sppm.
struct PhotonOptions {
    /// photon: photon paths shot for the maps; sppm: per iteration.
    std::uint32_t photons = 200000;
    /// photon: photons per density estimate (k); sppm: the photons a pixel's starting radius reaches.
    int nearest = 50;
    /// photon: the largest radius an estimate looks within; sppm: the largest starting radius; 0 = the scene
    /// sphere's radius / 20.
    float max_radius = 0.0f;
    /// photon: final gather rays per camera sample (0: the global map read at the gather point itself).
    int gather = 1;
    PhotonFilter filter = PhotonFilter::epanechnikov;  ///< photon: the density estimate's kernel
    /// sppm: the starting radius of every pixel's estimate in world units; 0 = for each pixel, the distance from its
    /// first visible point to the nearest-th photon of that iteration, between a pixel footprint and max_radius.
    float radius = 0.0f;
    float alpha = 2.0f / 3.0f;  ///< sppm: the fraction of new photons kept per iteration, in (0, 1)
};

/// Throws rtlab::Error naming the setting for photons < 1, nearest < 1, max_radius or radius < 0 or not finite,
/// gather < 0, or alpha outside (0, 1).
void check_photon_options(const PhotonOptions& options);

/// \brief The photon mapping integrator as the renderer's radiance source (see the file comment).
class PhotonIntegrator final : public StreamRadianceSource {
public:
    /// Shoots the photons (seed and threads as PhotonTraceSettings; a stop flag seen meanwhile leaves the maps
    /// empty: cancelled()) and builds the maps. scene and lights must outlive it. Throws rtlab::Error for bad
    /// options, or an environment texture (PathOptions::environment), which sends no photons.
    PhotonIntegrator(const SceneQuery& scene, const LightSet& lights, const SceneSphere& sphere, PathOptions path,
                     PhotonOptions options, std::uint64_t seed = 0, int threads = 0,
                     const std::atomic<bool>* stop = nullptr);

    RGB estimate(const Ray& ray, const SampleStream& stream, RayStats& stats) const override;

    const PhotonMap& caustic_map() const { return m_caustic; }
    const PhotonMap& global_map() const { return m_global; }
    std::uint32_t photons_shot() const { return m_shot; }
    const RayStats& photon_rays() const { return m_photon_rays; }
    bool cancelled() const { return m_cancelled; }
    float max_radius() const { return m_max_radius; }

private:
    RGB density(const PhotonMap& map, const PathVertex& v, std::uint32_t bounce) const;
    RGB gather_ray(const detail::WalkStart& start, const SampleStream& stream, RayStats& stats) const;

    const SceneQuery& m_scene;
    const LightSet& m_lights;
    PathOptions m_path;
    PhotonOptions m_options;
    float m_max_radius = 0.0f;
    PhotonMap m_caustic, m_global;
    std::uint32_t m_shot = 0;
    RayStats m_photon_rays;
    bool m_cancelled = false;
};

}  // namespace rtlab
