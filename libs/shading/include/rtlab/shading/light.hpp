#pragma once
/// \brief Light sources, created by name through a Registry: point, directional, spot, area, ambient.
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/core/registry.hpp>
#include <rtlab/shading/material.hpp>

#include <optional>

namespace rtlab {

/// \brief One sample of a light as seen from a point.
struct LightSample {
    Vec3 wi{0.0f, 0.0f, 1.0f};  ///< unit direction from the point towards the light
    Point3 position{0.0f};      ///< the sampled point on the light (shadow rays stop just short of it)
    bool at_infinity = false;   ///< directional: no position, shadow rays are unbounded
    RGB arriving;               ///< what multiplies Material::direct (already divided by the sample count)
};

/// \brief The rectangle an `area` light is, for the sampling integrators, which make it an emitting quad (so
/// that rays can hit it and multiple importance sampling applies): corner + a edge_u + b edge_v, emitting
/// `radiance` (intensity / area) towards edge_u x edge_v, or from both faces.
struct EmittingQuad {
    Point3 corner{0.0f};
    Vec3 edge_u{1.0f, 0.0f, 0.0f}, edge_v{0.0f, 0.0f, 1.0f};
    RGB radiance;
    bool two_sided = false;
};

/// \brief The cone a point-like delta light shines into: unit axis, cosine of the half-angle.
struct EmissionCone {
    Vec3 axis{0.0f, 0.0f, 1.0f};
    float cos_max = -1.0f;
};

/// \brief A light. sample() is const and thread-safe; its random numbers come from the caller.
class Light {
public:
    virtual ~Light() = default;
    /// Samples the light wants per shaded point (n x n for an area light, 1 for the others, 0 for ambient).
    virtual int sample_count() const { return 1; }
    /// Sample `index` of sample_count() seen from `point`; u is uniform in [0, 1)^2 (used by area lights).
    /// arriving is black where the light gives nothing (outside a spot's cone, behind an area light).
    virtual LightSample sample(const Point3& point, int index, Vec2 u, Convention convention) const = 0;
    /// Whether sample() reads u; false lets the caller skip hashing random numbers nobody uses.
    virtual bool uses_random_sample() const { return true; }
    /// Light arriving equally from every direction (ambient light), black for the others.
    virtual RGB ambient() const { return {}; }

    // What the sampling integrators (direct, path) ask beside sample(), always in the physical convention.
    /// The emitted power of a delta light (point, spot, directional), by which the integrators choose among
    /// lights; `scene_radius` bounds the scene (a directional light's power is its irradiance over the scene's
    /// disk). Black for a light that is not a delta light.
    virtual RGB power(float /*scene_radius*/) const { return {}; }
    /// Whether the light is a delta light the sampling integrators can use through sample() (index 0).
    virtual bool is_delta() const { return false; }
    /// The rectangle of an area light (nullopt for the others).
    virtual std::optional<EmittingQuad> emitting_quad() const { return std::nullopt; }
    /// A point-like delta light that shines into a cone only (a spot): photons are emitted in it. nullopt: every
    /// direction (the photon tracer reads the intensity of each through sample()).
    virtual std::optional<EmissionCone> emission_cone() const { return std::nullopt; }
};

using LightRegistry = Registry<Light>;

/// Registers point, directional, spot, area and ambient; each doc() lists the parameters.
void register_builtins(LightRegistry& registry);

/// A registry with category "light" and every built-in registered.
LightRegistry make_light_registry();

}  // namespace rtlab
