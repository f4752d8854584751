#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/mesh_surface.hpp>

namespace rtlab {

MeshShape::MeshShape(std::shared_ptr<const TriangleMesh> mesh, std::string_view method, const BuildOptions& options)
    : m_mesh(std::move(mesh)), m_options(options) {
    if (!m_mesh) throw Error("mesh shape: no mesh");
    m_accel = make_accelerator(method, *m_mesh, options);
    m_bounds = m_mesh->bounds();
}

bool MeshShape::intersect(const Ray& ray, SurfaceHit& hit) const {
    MeshHit h;
    if (!m_accel->intersect(ray, h)) return false;
    fill_mesh_hit(*m_mesh, h.primitive, ray, h.t, h.u, h.v, this, hit);
    return true;
}

}  // namespace rtlab
