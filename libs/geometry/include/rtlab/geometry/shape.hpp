#pragma once
/// \brief The interface every geometric shape answers for a ray.
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/surface_hit.hpp>
#include <rtlab/geometry/uv_footprint.hpp>

#include <optional>

namespace rtlab {

/// \brief A shape: bounds, closest hit in (ray.tmin, ray.tmax), and any-hit for shadow rays.
class Shape {
public:
    virtual ~Shape() = default;

    virtual AABB bounds() const = 0;
    /// Closest hit with ray.tmin < t < ray.tmax (open, as in the hit files of FORMATS.md, so a ray leaving
    /// a surface with tmin = 0 does not hit it again at t = 0); fills hit and returns true, else leaves it alone.
    virtual bool intersect(const Ray& ray, SurfaceHit& hit) const = 0;
    /// Whether anything blocks the ray for some tmin < t < tmax; may stop at the first blocker.
    virtual bool occluded(const Ray& ray) const = 0;

    /// Closest hits in two steps, for picking the nearest of several shapes before paying for one full
    /// record (a sphere's uv alone costs an atan2 and an acos): intersect_distance() gives the t intersect()
    /// would report, complete_hit() then fills the record for that t. Worth it only where the distance is
    /// much cheaper than the record, which the shape says by defers_record(); a mesh, whose record needs the
    /// triangle its traversal found, keeps the one-step intersect(). The defaults are correct for any shape.
    virtual bool defers_record() const { return false; }
    /// The t of intersect()'s hit, without the record; the default runs intersect() into a scratch record.
    virtual bool intersect_distance(const Ray& ray, float& t) const;
    /// The record intersect() would give for the hit intersect_distance() found at t on this ray; the default
    /// runs intersect() again with tmax just above t.
    virtual void complete_hit(const Ray& ray, float t, SurfaceHit& hit) const;
    /// complete_hit() for a caller that never reads hit.uv (a surface whose material has no textures): a shape
    /// whose uv is costly may leave it at its default; every other field is complete_hit()'s, bit for bit.
    /// The default is complete_hit().
    virtual void complete_hit_without_uv(const Ray& ray, float t, SurfaceHit& hit) const { complete_hit(ray, t, hit); }

    /// Where the shape's uv lies in world space, for the level of detail of a filtered texture on it (one map
    /// period of u along its equator or across its ring); nullopt for a shape without one such footprint
    /// (quads, boxes, meshes...).
    std::optional<UvFootprint> uv_footprint() const { return uv_footprint(Mat4(1.0f)); }
    /// The footprint of the shape placed by `to_world`. An Instance passes its matrix on (composed with
    /// `to_world`) instead of transforming its child's footprint, so that a transformed sphere's footprint is
    /// worked out from the one matrix, bit for bit as sphere_footprint() gives it. nullopt by default.
    virtual std::optional<UvFootprint> uv_footprint(const Mat4& to_world) const;
};

}  // namespace rtlab
