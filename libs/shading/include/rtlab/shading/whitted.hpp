#pragma once
/// \brief The Whitted recursion: direct light with transparent shadows, mirror reflection, refraction.
#include <rtlab/core/sample_hash.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/scene_query.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace rtlab {

/// \brief Rays traced by kind. Each thread keeps its own and the caller sums them (plain integers).
struct RayStats {
    std::uint64_t shadow = 0;     ///< shadow ray segments (one more per transmissive surface crossed)
    std::uint64_t reflected = 0;  ///< mirror reflections, total internal reflections included
    std::uint64_t refracted = 0;  ///< refractions and rays continuing through cut-outs (opacity < 1)

    RayStats& operator+=(const RayStats& o) {
        shadow += o.shadow;
        reflected += o.reflected;
        refracted += o.refracted;
        return *this;
    }
};

/// \brief Integrator settings.
struct WhittedOptions {
    Convention convention = Convention::physical;
    int max_depth = 5;         ///< secondary rays stop after this many reflections/refractions
    float min_weight = 1e-3f;  ///< a secondary ray whose weight (largest component) falls below is not traced
    int max_crossings = 64;    ///< transmissive surfaces a shadow ray or a cut-out ray crosses at most
    RGB background;            ///< radiance of escaping rays, when there is no environment
    std::shared_ptr<const Texture> environment;  ///< looked up with TextureLookup::direction (a cube map)
};

/// \brief Whitted-style ray tracer over a SceneQuery and a list of lights.
///
/// Random numbers come from sample_hash(key, dimension); dimensions from kLightDimension up are area-light
/// samples, two per sample in the order of the lights, and key.bounce is the depth of the ray.
class WhittedIntegrator {
public:
    static constexpr std::uint32_t kLightDimension = 64;

    WhittedIntegrator(const SceneQuery& scene, std::vector<std::shared_ptr<const Light>> lights,
                      WhittedOptions options = {});

    /// Radiance arriving along -ray.direction at ray.origin.
    RGB radiance(const Ray& ray, const SampleKey& key, RayStats& stats) const;
    /// out[i] = radiance(rays[i], keys[i]) for a group of coherent rays (camera rays, best as 4 x 2 pixel tiles),
    /// bit for bit: their first hits come from the scene's packet query (SceneQuery::intersect_surface_packet).
    void radiance_packet(std::span<const Ray> rays, std::span<const SampleKey> keys, std::span<RGB> out,
                         RayStats& stats) const;
    /// Whether radiance_packet traces rays together (SceneQuery::traces_packets); else it calls radiance() per ray.
    bool traces_packets() const { return m_scene.traces_packets(); }

    /// The fraction of a light sample's light that reaches `from`: 0 if an opaque caster is in the way,
    /// else the product over the transmissive surfaces crossed in order of (1 - opacity) + opacity kt, and
    /// exp(-absorption d) for every stretch d inside an absorbing medium.
    RGB transmittance(const SurfaceHit& from, const LightSample& light, RayStats& stats) const;

    const WhittedOptions& options() const { return m_options; }

private:
    RGB trace(const Ray& ray, const SampleKey& key, int depth, int crossings, float weight, RayStats& stats) const;
    RGB escaped(const Ray& ray) const;
    /// A first shadow segment's answer traced beforehand: kClear or kBlocked (by an opaque caster), or kNotTraced.
    static constexpr std::uint8_t kClear = 0, kBlocked = 1, kNotTraced = 2;
    /// What radiance_packet found beforehand for one hit and one light: the light's sample (`sampled`) and, for a
    /// sample that lights the surface (`lit`), what its first shadow segment met (kClear or kBlocked).
    struct KnownLight {
        // Left unset until radiance_packet samples the light: its table holds kPacketLights entries a hit, and
        // setting them all up front cost the bunny scene more than the second sample saved.
        KnownLight() {}
        union {
            LightSample sample;
        };
        bool sampled;
        bool lit;
        std::uint8_t shadow;
    };
    /// trace() once the ray (of direction length dlen) has met `hit` on a surface of `info`. known: null, or per
    /// light (the first kPacketLights) what radiance_packet found for this hit beforehand, used as it is.
    /// Inline, defined in whitted.cpp (its only caller): as a call of its own it cost the Whitted scene 2% more
    /// instructions.
    inline RGB shade(const Ray& ray, float dlen, const SurfaceHit& hit, const SurfaceInfo& info, const SampleKey& key,
                     int depth, int crossings, float weight, RayStats& stats, const KnownLight* known = nullptr) const;
    /// Lights (the first ones) whose samples and first shadow segments radiance_packet works out beforehand.
    static constexpr std::size_t kPacketLights = 8;
    RGB transmittance(const SurfaceHit& from, const LightSample& light, RayStats& stats, std::uint8_t known) const;

    /// What the light loop asks every light at every hit, asked once here (the answers of a const light).
    struct LightEntry {
        const Light* light;
        RGB ambient;
        int sample_count;
        bool uses_random_sample;
    };

    const SceneQuery& m_scene;
    std::vector<std::shared_ptr<const Light>> m_lights;
    std::vector<LightEntry> m_entries;
    WhittedOptions m_options;
};

}  // namespace rtlab
