#pragma once
/// \brief What the sampling integrators (direct, path) ask of a light: emitting shapes sampled by area (spheres
/// by the cone they subtend), a uniform environment, and the delta lights (point, spot, directional).
///
/// Every answer is in the physical convention. Densities are over the solid angle seen from the shaded point, so
/// that a light sample and a BSDF sample meeting the same light can be weighed against each other (multiple
/// importance sampling); a delta light has no density (pdf 1, is_delta()).
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/shading/light.hpp>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace rtlab {

/// \brief One sample of a light seen from a point.
struct EmitterSample {
    Vec3 wi{0.0f, 0.0f, 1.0f};  ///< unit, from the point towards the light
    Point3 position{0.0f};      ///< the point on the light (a shadow ray stops just short of it)
    bool at_infinity = false;   ///< environment and directional light: the shadow ray is unbounded
    RGB radiance;               ///< what arrives along -wi; for a delta light, what multiplies f |cos|
    float pdf = 0.0f;           ///< solid-angle density of wi; 1 for a delta light
};

/// \brief A sphere bounding the scene: lights at infinity (the environment, a directional light) send photons from
/// a disk of this radius, perpendicular to their direction, so that every photon can reach the scene.
struct SceneSphere {
    Point3 centre{0.0f};
    float radius = 1.0f;
};

/// \brief One photon leaving a light (Emitter::sample_le): where it starts, where it goes, with what densities.
///
/// A photon tracer gives the photon `power` / (the light's probability of being chosen) and divides the sum of what
/// it deposits by the number of photons shot. The densities are for an algorithm that weighs light paths against
/// others (bidirectional methods); a delta position or direction has density 1 and its flag set.
struct EmissionSample {
    Point3 position{0.0f};             ///< on the light, or on the disk of SceneSphere for a light at infinity
    Vec3 direction{0.0f, 0.0f, 1.0f};  ///< unit, the way the photon travels
    Normal3 normal{0.0f};              ///< the emitting surface's (front) normal; 0 for a point or a light at infinity
    RGB radiance;                 ///< Le along `direction`; a point light's intensity; a directional light's irradiance
    float pdf_position = 0.0f;    ///< area density of `position` (1 when delta_position)
    float pdf_direction = 0.0f;   ///< solid-angle density of `direction` (1 when delta_direction)
    bool delta_position = false;  ///< point and spot lights
    bool delta_direction = false;  ///< directional light
    /// radiance |cos(normal, direction)| / (pdf_position pdf_direction): the flux the photon stands for (cos is 1 for
    /// a point and at infinity).
    RGB power;
};

/// \brief A light as the sampling integrators see it. Thread-safe: all methods are const.
class Emitter {
public:
    virtual ~Emitter() = default;
    /// A direction towards the light from p, u uniform in [0, 1)^2; nullopt when nothing arrives (behind a
    /// one-sided light, outside a spot's cone) or the draw is degenerate.
    virtual std::optional<EmitterSample> sample_li(const Point3& p, const Vec2& u) const = 0;
    /// The density with which sample_li(p) draws the direction wi that meets the light at `on_light` with the
    /// light's outward geometric normal `normal` (ignored by an environment); 0 for a delta light.
    virtual float pdf_li(const Point3& p, const Vec3& wi, const Point3& on_light, const Normal3& normal) const = 0;
    /// Emitted power (flux), by which lights are chosen.
    virtual RGB power() const = 0;
    virtual bool is_delta() const { return false; }
    /// A photon leaving the light (photon mapping): u_position picks the point, u_direction the direction, both
    /// uniform in [0, 1)^2; `scene` bounds the scene for lights at infinity. nullopt when the draw is degenerate, or
    /// for a light that cannot emit photons (the default: an emitter that does not override this sends none, so a
    /// photon map misses its light). Area lights: a point uniform by area, a cosine-weighted direction about the
    /// front normal (either face, half each, when two-sided); point: uniform over the sphere; spot: uniform in its
    /// cone (Light::emission_cone); directional and environment: a point uniform on the disk of scene.radius
    /// perpendicular to the direction, centred on the scene's centre pushed scene.radius back towards the light. An
    /// environment map does the same with its direction drawn as sample_li draws it: power = Le / (pdf_direction
    /// pdf_position), pdf_position = 1 / (pi scene.radius^2).
    virtual std::optional<EmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                                    const SceneSphere& scene) const;
};

/// \brief The surface an AreaEmitter samples, in world space.
struct EmitterShape {
    enum class Kind { triangles, disk, sphere };
    Kind kind = Kind::triangles;
    /// triangles: each counter-clockwise about its emitting (front) normal, cross(b - a, c - a).
    std::vector<std::array<Point3, 3>> triangles;
    Point3 centre{0.0f};                       ///< disk, sphere
    Normal3 normal{0.0f, 0.0f, 1.0f};          ///< disk: unit, the front face's normal
    float radius = 0.0f, inner_radius = 0.0f;  ///< disk (annulus with inner_radius > 0), sphere
    bool inward = false;                       ///< sphere: the front face is the inside (a reversed sphere)
};

/// \brief An emitting surface of constant radiance: triangles chosen by area (a cumulative table, binary search)
/// then a uniform point, a disk uniformly by area, a sphere seen from outside by the cone it subtends (uniform
/// over it) and from inside uniformly by area. One-sided (the front face) unless two_sided.
class AreaEmitter final : public Emitter {
public:
    /// Throws rtlab::Error for a shape of no area.
    AreaEmitter(EmitterShape shape, const RGB& radiance, bool two_sided);

    std::optional<EmitterSample> sample_li(const Point3& p, const Vec2& u) const override;
    float pdf_li(const Point3& p, const Vec3& wi, const Point3& on_light, const Normal3& normal) const override;
    /// radiance x area x pi, twice that when two-sided.
    RGB power() const override;
    std::optional<EmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                            const SceneSphere& scene) const override;

    float area() const { return m_area; }
    const RGB& radiance() const { return m_radiance; }
    bool two_sided() const { return m_two_sided; }

private:
    struct SurfacePoint {
        Point3 point;
        Normal3 normal;  // the front face's
    };
    SurfacePoint sample_area(const Vec2& u) const;
    bool sphere_cone(const Point3& p, float& cos_max, float& one_minus_cos_max) const;

    EmitterShape m_shape;
    RGB m_radiance;
    bool m_two_sided;
    float m_area = 0.0f;
    std::vector<float> m_cdf;        // triangles: cumulative area, last = m_area
    std::vector<Normal3> m_normals;  // triangles: each one's unit front normal, worked out once
};

/// \brief Light from infinitely far away, by direction: what rays that escape the scene see, and a light the
/// sampling integrators sample (its samples are at_infinity; pdf_li reads only wi).
class EnvironmentEmitter : public Emitter {
public:
    /// The radiance arriving at the scene along -direction (direction points from the scene to the sky; any
    /// length > 0).
    virtual RGB radiance(const Vec3& direction) const = 0;
    /// The same environment lighting a scene of radius scene_radius: its power() is the radiance integrated over
    /// the sphere of directions times pi r^2 (what a disk of the scene's size intercepts), which weighs it against
    /// the scene's other lights.
    virtual std::shared_ptr<const EnvironmentEmitter> for_scene_radius(float scene_radius) const = 0;
    /// A photon from the disk of `scene` (Emitter::sample_le) whose direction is drawn by sample_li.
    std::optional<EmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                            const SceneSphere& scene) const override;
};

/// \brief Radiance arriving equally from every direction, sampled uniformly over the sphere of directions.
class UniformEnvironment final : public EnvironmentEmitter {
public:
    /// scene_radius bounds the scene: the power is radiance x 4 pi x pi r^2.
    UniformEnvironment(const RGB& radiance, float scene_radius) : m_radiance(radiance), m_radius(scene_radius) {}
    std::optional<EmitterSample> sample_li(const Point3& p, const Vec2& u) const override;
    float pdf_li(const Point3&, const Vec3&, const Point3&, const Normal3&) const override;
    RGB power() const override;
    RGB radiance(const Vec3&) const override { return m_radiance; }
    std::shared_ptr<const EnvironmentEmitter> for_scene_radius(float scene_radius) const override {
        return std::make_shared<UniformEnvironment>(m_radiance, scene_radius);
    }
    std::optional<EmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                            const SceneSphere& scene) const override;
    const RGB& radiance() const { return m_radiance; }

private:
    RGB m_radiance;
    float m_radius;
};

/// \brief A delta light (Light::is_delta()) through Light::sample() in the physical convention.
class DeltaEmitter final : public Emitter {
public:
    /// Throws rtlab::Error for a null light or one that is not a delta light.
    DeltaEmitter(std::shared_ptr<const Light> light, float scene_radius);
    std::optional<EmitterSample> sample_li(const Point3& p, const Vec2& u) const override;
    float pdf_li(const Point3&, const Vec3&, const Point3&, const Normal3&) const override { return 0.0f; }
    RGB power() const override { return m_power; }
    bool is_delta() const override { return true; }
    std::optional<EmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                            const SceneSphere& scene) const override;

private:
    std::shared_ptr<const Light> m_light;
    RGB m_power;
};

/// Uniform direction on the unit sphere from u in [0, 1)^2 (density 1 / (4 pi)).
Vec3 sample_uniform_sphere(const Vec2& u);
/// Uniform direction in the cone of half-angle acos(cos_max) about +z from u in [0, 1)^2 (density
/// 1 / (2 pi (1 - cos_max))).
Vec3 sample_uniform_cone(const Vec2& u, float cos_max);

}  // namespace rtlab
