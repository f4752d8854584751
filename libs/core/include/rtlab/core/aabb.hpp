#pragma once
/// \brief Axis-aligned bounding box and its exact slab test.
#include <rtlab/core/interval.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/core/ray.hpp>

#include <optional>

namespace rtlab {

/// \brief Axis-aligned box [lo, hi]; the default one is empty (lo = +inf, hi = -inf).
struct AABB {
    Point3 lo{kInfinity};
    Point3 hi{-kInfinity};

    static AABB from_points(const Point3& a, const Point3& b) { return {glm::min(a, b), glm::max(a, b)}; }

    bool is_empty() const { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
    void expand(const Point3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void expand(const AABB& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    AABB united(const AABB& b) const { return {glm::min(lo, b.lo), glm::max(hi, b.hi)}; }
    AABB intersected(const AABB& b) const { return {glm::max(lo, b.lo), glm::min(hi, b.hi)}; }
    Vec3 extent() const { return hi - lo; }
    Point3 center() const { return 0.5f * (lo + hi); }
    float diagonal() const { return is_empty() ? 0.0f : glm::length(hi - lo); }
    float surface_area() const;
    /// Axis of the largest extent.
    int longest_axis() const { return max_dimension(extent()); }
    bool contains(const Point3& p) const;
    Interval axis(int a) const { return {lo[a], hi[a]}; }

    /// Parameter range where the ray is inside the box, clipped to [ray.tmin, ray.tmax]; nullopt on a miss.
    ///
    /// The slab test is BoxRay's (rtlab/core/box_ray.hpp), the one the accel trees use, so a box and a
    /// tree never disagree about a ray. Exact where the naive slab test is not: a direction component of
    /// +0, -0 or a denormal constrains nothing when the origin is within the slab or on its planes, and
    /// rejects when it is outside; the far distance is enlarged by 2 gamma(3) (Ize 2013) so rounding never
    /// drops a true hit; and any NaN or infinity in the ray, an empty box, tmin > tmax or an entry at
    /// infinity is a miss.
    std::optional<Interval> intersect(const Ray& ray) const;
};

}  // namespace rtlab
