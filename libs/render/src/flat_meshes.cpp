#include "flat_meshes.hpp"

#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/mesh_surface.hpp>

#include <algorithm>
#include <string>

namespace rtlab {

const MeshShape* FlatMeshes::joinable(const Shape& shape, std::size_t max_triangles) {
    const auto* mesh = dynamic_cast<const MeshShape*>(&shape);
    if (!mesh || mesh->mesh().triangle_count() > max_triangles) return nullptr;
    if (mesh->build_options().triangle_test != TriangleTest::watertight) return nullptr;
    const std::vector<std::string> kd = kd_tree_methods();
    if (std::find(kd.begin(), kd.end(), mesh->accelerator().name()) == kd.end()) return nullptr;
    return mesh;
}

FlatMeshes::FlatMeshes(std::vector<Part> parts) : m_parts(std::move(parts)) {
    std::size_t vertices = 0, triangles = 0;
    for (const Part& p : m_parts) {
        vertices += p.mesh->mesh().vertex_count();
        triangles += p.mesh->mesh().triangle_count();
    }
    if (vertices > UINT32_MAX || triangles > UINT32_MAX) throw Error("scene: too many triangles in small meshes");
    m_merged.positions.reserve(vertices);
    m_merged.triangles.reserve(triangles);
    m_part_of.reserve(triangles);
    m_first.reserve(m_parts.size());
    for (std::uint32_t k = 0; k < m_parts.size(); ++k) {
        const TriangleMesh& mesh = m_parts[k].mesh->mesh();
        const auto base = static_cast<std::uint32_t>(m_merged.positions.size());
        m_first.push_back(static_cast<std::uint32_t>(m_merged.triangles.size()));
        m_merged.positions.insert(m_merged.positions.end(), mesh.positions.begin(), mesh.positions.end());
        for (const auto& tri : mesh.triangles) {
            m_merged.triangles.push_back({base + tri[0], base + tri[1], base + tri[2]});
            m_part_of.push_back(k);
        }
    }
    // The watertight test the parts' trees run; any leaf width gives the same answers.
    m_accel = make_kd_tree("kd-sah", m_merged, BuildOptions{});
}

std::size_t FlatMeshes::complete(const Ray& ray, const MeshHit& found, SurfaceHit& hit) const {
    const std::uint32_t k = m_part_of[found.primitive];
    const Part& part = m_parts[k];
    fill_mesh_hit(part.mesh->mesh(), found.primitive - m_first[k], ray, found.t, found.u, found.v, part.mesh, hit);
    return part.object;
}

std::size_t FlatMeshes::bytes() const {
    const AccelStats stats = m_accel->stats();
    return m_parts.capacity() * sizeof(Part) + (m_first.capacity() + m_part_of.capacity()) * sizeof(std::uint32_t) +
           m_merged.positions.capacity() * sizeof(Point3) +
           m_merged.triangles.capacity() * sizeof(m_merged.triangles[0]) +
           static_cast<std::size_t>(std::max<std::int64_t>(stats.bytes, 0));
}

}  // namespace rtlab
