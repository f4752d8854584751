#pragma once
/// \brief Flat disk: a circle in a plane.
#include <rtlab/geometry/shape.hpp>

namespace rtlab {

/// \brief Disk by centre, unit normal (its outside) and radius; uv = (radius fraction, angle / 2 pi).
class Disk final : public Shape {
public:
    Disk(const Point3& centre, const Normal3& normal, float radius);
    AABB bounds() const override;
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;

private:
    bool hit_t(const Ray& ray, float& t) const;
    Point3 m_centre;
    Normal3 m_normal;
    float m_radius;
};

}  // namespace rtlab
