#pragma once
/// \brief Flat disk: a circle in a plane, or an annulus (a disk with a hole).
#include <rtlab/geometry/shape.hpp>

namespace rtlab {

/// \brief Disk by centre, unit normal (its outside), radius and an optional inner radius (an annulus:
/// Saturn's rings). uv = ((r - inner) / (radius - inner), angle / 2 pi), so u spans [0, 1] across the ring
/// and a radial strip texture (inner edge at u = 0) maps onto it whatever the inner radius.
class Disk final : public Shape {
public:
    /// Throws rtlab::Error unless 0 <= inner_radius < radius, both finite, and the normal is non-zero.
    Disk(const Point3& centre, const Normal3& normal, float radius, float inner_radius = 0.0f);
    AABB bounds() const override;
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;

private:
    bool hit_t(const Ray& ray, float& t) const;
    Point3 m_centre;
    Normal3 m_normal;
    float m_radius;
    float m_inner_radius;
};

}  // namespace rtlab
