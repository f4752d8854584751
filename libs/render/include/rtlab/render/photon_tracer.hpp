#pragma once
/// \brief Shooting photons: paths from the lights, in proportion to their power, traced with the materials'
/// importance mode and stored where they meet a surface with non-specular lobes.
#include <rtlab/core/sample_stream.hpp>
#include <rtlab/render/photon_map.hpp>
#include <rtlab/shading/light_set.hpp>
#include <rtlab/shading/scene_query.hpp>
#include <rtlab/shading/whitted.hpp>

#include <atomic>
#include <cstdint>
#include <vector>

namespace rtlab {

/// SampleKey::x of every photon's stream: above any pixel column (images are at most 16384 wide), so photon
/// streams never share a key with a camera sample.
inline constexpr std::uint32_t kPhotonStreamX = 0xffffffffu;

/// \brief Which photons to keep, by PhotonPath (bits 1 << path).
using PhotonPathMask = std::uint32_t;
inline constexpr PhotonPathMask kKeepDirect = 1u << static_cast<unsigned>(PhotonPath::direct);
inline constexpr PhotonPathMask kKeepCaustic = 1u << static_cast<unsigned>(PhotonPath::caustic);
inline constexpr PhotonPathMask kKeepIndirect = 1u << static_cast<unsigned>(PhotonPath::indirect);
inline constexpr PhotonPathMask kKeepAll = kKeepDirect | kKeepCaustic | kKeepIndirect;

/// \brief How to shoot photons.
///
/// Photon i of pass p is a pure function of (sequence, seed, p, i): its numbers come from
/// SampleStream(sequence, {seed, kPhotonStreamX, p, i, 0}), pair 0 choosing the light (x), pair 1 the point on it,
/// pair 2 the direction, and at its b-th hit (b from 0) pair 3 + 2 b the lobe (x) and Russian roulette (y), pair
/// 4 + 2 b the scattered direction. Under sobol the photons of one pass are one Owen-scrambled Sobol sequence over i:
/// emission and first bounces are stratified over the whole pass.
struct PhotonTraceSettings {
    std::uint32_t photons = 100000;  ///< photon paths shot (each counts in the density estimates' divisor)
    std::uint64_t seed = 0;
    std::uint32_t pass = 0;  ///< a different set of photons per pass (SPPM's iterations)
    /// Photons are stored at their first max_depth hits (bounces 0 .. max_depth - 1): a camera vertex at depth
    /// d >= 1 can use a photon of b bounces when d + b <= max_depth, PathOptions::max_depth's count.
    int max_depth = 8;
    /// Russian roulette after every scattering, surviving with the ratio of the throughput's channel means after and
    /// before it (at most 1), so photons keep about the power they left with (even photon powers make the densest
    /// estimates); false traces every photon to max_depth (tests of energy conservation).
    bool roulette = true;
    PhotonPathMask keep = kKeepAll;
    SampleSequence sequence = SampleSequence::sobol;
    int threads = 0;  ///< 0: as many as the machine has; the photons do not depend on it
};

/// \brief Shot photons: the kept ones in photon index order (a photon's hits in path order), the rays traced
/// (emission and scattering rays count as reflected or refracted by the lobe that sent them; emission as reflected).
struct PhotonTrace {
    std::vector<Photon> photons;
    std::uint32_t shot = 0;  ///< photon paths traced (settings.photons unless cancelled)
    RayStats rays;
    bool cancelled = false;  ///< `stop` was seen: the photons are incomplete, use none of them
};

/// Shoots settings.photons photons from `lights` (LightSet::choose, each photon's power divided by its light's
/// probability) into `scene`; `sphere` bounds the scene for lights at infinity. Blocks of photons are traced in
/// parallel into their own lists, joined in index order: the result is the same bytes for any thread count. A
/// photon is stored at every hit on a material that reflects direct light (Material::reflects_direct_light: it has
/// non-delta lobes), with its path class (PhotonPath: the lobes drawn before), if settings.keep has it. Throws
/// rtlab::Error for max_depth < 0.
PhotonTrace trace_photons(const SceneQuery& scene, const LightSet& lights, const SceneSphere& sphere,
                          const PhotonTraceSettings& settings, const std::atomic<bool>* stop = nullptr);

}  // namespace rtlab
