#pragma once
/// \brief Parallelogram given by a corner and two edges.
#include <rtlab/geometry/shape.hpp>

#include <cmath>

namespace rtlab {

/// \brief Points corner + alpha edge_u + beta edge_v for alpha, beta in [0, 1]; uv = (alpha, beta), as in
/// the course write-ups; outside = the side of edge_u x edge_v.
class Quad final : public Shape {
public:
    Quad(const Point3& corner, const Vec3& edge_u, const Vec3& edge_v);
    AABB bounds() const override;
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;
    // What an area light samples the quad by.
    const Point3& corner() const { return m_corner; }
    const Vec3& edge_u() const { return m_u; }
    const Vec3& edge_v() const { return m_v; }

    /// The distance t in (tmin, tmax) and plane coordinates of the ray's hit; false for a miss. Inline, with
    /// fill_record() below, so that a scene's list tests a quad without a virtual call and fills the record
    /// only for the hit that stays nearest.
    bool hit_params(const Ray& ray, float& t, float& alpha, float& beta) const;
    /// The record of the hit hit_params() found at t, alpha, beta (what intersect() fills).
    void fill_record(const Ray& ray, float t, float alpha, float beta, SurfaceHit& hit) const;

private:
    Point3 m_corner;
    Vec3 m_u, m_v, m_normal, m_w;  // m_w = n / (n . n), for the plane coordinates
    Vec3 m_tangent;                // every hit's unit tangent
};

inline bool Quad::hit_params(const Ray& ray, float& t, float& alpha, float& beta) const {
    const float denom = glm::dot(m_normal, ray.direction);
    if (denom == 0.0f || !std::isfinite(denom)) return false;
    t = glm::dot(m_normal, m_corner - ray.origin) / denom;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    const Vec3 planar = ray.at(t) - m_corner;
    alpha = glm::dot(m_w, glm::cross(planar, m_v));
    beta = glm::dot(m_w, glm::cross(m_u, planar));
    return alpha >= 0.0f && alpha <= 1.0f && beta >= 0.0f && beta <= 1.0f;
}

}  // namespace rtlab
