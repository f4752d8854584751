#pragma once
/// \brief Parallelogram given by a corner and two edges.
#include <rtlab/geometry/shape.hpp>

namespace rtlab {

/// \brief Points corner + alpha edge_u + beta edge_v for alpha, beta in [0, 1]; uv = (alpha, beta), as in
/// the course write-ups; outside = the side of edge_u x edge_v.
class Quad final : public Shape {
public:
    Quad(const Point3& corner, const Vec3& edge_u, const Vec3& edge_v);
    AABB bounds() const override;
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;

private:
    bool hit_params(const Ray& ray, float& t, float& alpha, float& beta) const;
    Point3 m_corner;
    Vec3 m_u, m_v, m_normal, m_w;  // m_w = n / (n . n), for the plane coordinates
    Vec3 m_tangent;                // every hit's unit tangent
};

}  // namespace rtlab
