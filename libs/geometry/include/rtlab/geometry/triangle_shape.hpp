#pragma once
/// \brief One triangle of a mesh as a shape, with the mesh's vertex normals and uvs when it has them.
#include <rtlab/geometry/shape.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <memory>

namespace rtlab {

/// \brief Triangle `index` of a shared mesh, intersected with the watertight test. The shading normal
/// interpolates vertex normals (when the mesh has them) and uv interpolates vertex uvs (else it is the
/// barycentric pair); the geometric normal follows the winding (p1 - p0) x (p2 - p0).
class TriangleShape final : public Shape {
public:
    TriangleShape(std::shared_ptr<const TriangleMesh> mesh, std::uint32_t index);
    AABB bounds() const override { return m_mesh->triangle_bounds(m_index); }
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;

private:
    std::shared_ptr<const TriangleMesh> m_mesh;
    std::uint32_t m_index;
};

}  // namespace rtlab
