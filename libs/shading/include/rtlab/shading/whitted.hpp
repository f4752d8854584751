#pragma once
/// \brief The Whitted recursion: direct light with transparent shadows, mirror reflection, refraction.
#include <rtlab/core/sample_hash.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/scene_query.hpp>

#include <cstdint>
#include <memory>
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

    /// The fraction of a light sample's light that reaches `from`: 0 if an opaque caster is in the way,
    /// else the product over the transmissive surfaces crossed in order of (1 - opacity) + opacity kt, and
    /// exp(-absorption d) for every stretch d inside an absorbing medium.
    RGB transmittance(const SurfaceHit& from, const LightSample& light, RayStats& stats) const;

    const WhittedOptions& options() const { return m_options; }

private:
    RGB trace(const Ray& ray, const SampleKey& key, int depth, int crossings, float weight, RayStats& stats) const;
    RGB escaped(const Ray& ray) const;

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
