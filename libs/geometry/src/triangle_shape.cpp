#include <rtlab/core/error.hpp>
#include <rtlab/geometry/mesh_surface.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_shape.hpp>

#include <string>

namespace rtlab {

TriangleShape::TriangleShape(std::shared_ptr<const TriangleMesh> mesh, std::uint32_t index)
    : m_mesh(std::move(mesh)), m_index(index) {
    if (!m_mesh || index >= m_mesh->triangle_count())
        throw Error("triangle shape: index " + std::to_string(index) + " is not a triangle of the mesh");
}

bool TriangleShape::intersect(const Ray& ray, SurfaceHit& hit) const {
    const auto h = intersect_watertight(WatertightRay(ray), ray.tmin, ray.tmax, m_mesh->corner(m_index, 0),
                                        m_mesh->corner(m_index, 1), m_mesh->corner(m_index, 2));
    if (!h) return false;
    fill_mesh_hit(*m_mesh, m_index, ray, h->t, h->u, h->v, this, hit);
    return true;
}

bool TriangleShape::occluded(const Ray& ray) const {
    return intersect_watertight(WatertightRay(ray), ray.tmin, ray.tmax, m_mesh->corner(m_index, 0),
                                m_mesh->corner(m_index, 1), m_mesh->corner(m_index, 2))
        .has_value();
}

}  // namespace rtlab
