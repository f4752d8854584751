#include <rtlab/core/error.hpp>
#include <rtlab/geometry/quad.hpp>

#include "hit_fill.hpp"

namespace rtlab {

Quad::Quad(const Point3& corner, const Vec3& edge_u, const Vec3& edge_v) : m_corner(corner), m_u(edge_u), m_v(edge_v) {
    const Vec3 n = glm::cross(edge_u, edge_v);
    if (!(glm::dot(n, n) > 0.0f) || !is_finite(n)) throw Error("quad: the edges must be finite and not parallel");
    m_normal = glm::normalize(n);
    m_w = n / glm::dot(n, n);
    m_tangent = geometry::unit_tangent(m_u, m_normal);
}

AABB Quad::bounds() const {
    AABB b;
    for (const Point3& p : {m_corner, m_corner + m_u, m_corner + m_v, m_corner + m_u + m_v}) b.expand(p);
    return b;
}

bool Quad::intersect(const Ray& ray, SurfaceHit& hit) const {
    float t, alpha, beta;
    if (!hit_params(ray, t, alpha, beta)) return false;
    fill_record(ray, t, alpha, beta, hit);
    return true;
}

void Quad::fill_record(const Ray& ray, float t, float alpha, float beta, SurfaceHit& hit) const {
    // Rebuilt from the parameters, so the point is on the quad's plane but for the rounding of these three
    // terms (gamma(3)); two more for the plane the test uses, whose unit normal is rounded off the edges'.
    const Point3 p = m_corner + alpha * m_u + beta * m_v;
    const Vec3 error = gamma_bound(5) * (glm::abs(m_corner) + glm::abs(alpha * m_u) + glm::abs(beta * m_v));
    geometry::fill_hit_unit_tangent(hit, ray, t, p, error, m_normal, {alpha, beta}, m_tangent, 0, this);
}

bool Quad::occluded(const Ray& ray) const {
    float t, alpha, beta;
    return hit_params(ray, t, alpha, beta);
}

}  // namespace rtlab
