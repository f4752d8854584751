#include <rtlab/core/error.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_shape.hpp>

#include "hit_fill.hpp"

#include <string>

namespace rtlab {

TriangleShape::TriangleShape(std::shared_ptr<const TriangleMesh> mesh, std::uint32_t index)
    : m_mesh(std::move(mesh)), m_index(index) {
    if (!m_mesh || index >= m_mesh->triangle_count())
        throw Error("triangle shape: index " + std::to_string(index) + " is not a triangle of the mesh");
}

bool TriangleShape::intersect(const Ray& ray, SurfaceHit& hit) const {
    const Point3 &p0 = m_mesh->corner(m_index, 0), &p1 = m_mesh->corner(m_index, 1), &p2 = m_mesh->corner(m_index, 2);
    const auto h = intersect_watertight(WatertightRay(ray), ray.tmin, ray.tmax, p0, p1, p2);
    if (!h) return false;
    const float w = 1.0f - h->u - h->v;
    const Normal3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    const auto& tri = m_mesh->triangles[m_index];
    Vec2 uv(h->u, h->v);
    Vec3 dpdu = p1 - p0;
    if (m_mesh->has_uvs()) {
        const Vec2 &t0 = m_mesh->uvs[tri[0]], &t1 = m_mesh->uvs[tri[1]], &t2 = m_mesh->uvs[tri[2]];
        uv = w * t0 + h->u * t1 + h->v * t2;
        // dP/du from the uv parametrisation, when it is not degenerate.
        const Vec2 d1 = t1 - t0, d2 = t2 - t0;
        const float det = d1.x * d2.y - d1.y * d2.x;
        if (det != 0.0f) dpdu = (d2.y * (p1 - p0) - d1.y * (p2 - p0)) / det;
    }
    geometry::fill_hit(hit, ray, h->t, w * p0 + h->u * p1 + h->v * p2, n, uv, dpdu, m_index, this);
    if (m_mesh->has_normals()) {
        const Normal3 s = w * m_mesh->normals[tri[0]] + h->u * m_mesh->normals[tri[1]] + h->v * m_mesh->normals[tri[2]];
        if (glm::dot(s, s) > 0.0f && is_finite(s)) {
            hit.shading_normal = glm::normalize(s);
            const Vec3 t = hit.tangent - glm::dot(hit.tangent, hit.shading_normal) * hit.shading_normal;
            if (glm::dot(t, t) > 0.0f) hit.tangent = glm::normalize(t);
        }
    }
    return true;
}

bool TriangleShape::occluded(const Ray& ray) const {
    return intersect_watertight(WatertightRay(ray), ray.tmin, ray.tmax, m_mesh->corner(m_index, 0),
                                m_mesh->corner(m_index, 1), m_mesh->corner(m_index, 2))
        .has_value();
}

}  // namespace rtlab
