#pragma once
/// \brief The interface every geometric shape answers for a ray.
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/surface_hit.hpp>

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
};

}  // namespace rtlab
