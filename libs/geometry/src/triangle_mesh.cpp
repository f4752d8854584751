#include <rtlab/core/error.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <glm/gtc/type_precision.hpp>

#include <string>

namespace rtlab {

AABB TriangleMesh::triangle_bounds(std::size_t i) const {
    AABB b;
    for (int k = 0; k < 3; ++k) b.expand(corner(i, k));
    return b;
}

AABB TriangleMesh::bounds() const {
    AABB b;
    for (const auto& tri : triangles)
        for (std::uint32_t index : tri) b.expand(positions[index]);
    return b;
}

bool TriangleMesh::is_degenerate(std::size_t i) const {
    return is_degenerate_triangle(corner(i, 0), corner(i, 1), corner(i, 2));
}

std::size_t TriangleMesh::degenerate_count() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < triangles.size(); ++i) n += is_degenerate(i) ? 1 : 0;
    return n;
}

void TriangleMesh::validate() const {
    if (!normals.empty() && normals.size() != positions.size())
        throw Error("mesh has " + std::to_string(normals.size()) + " normals for " + std::to_string(positions.size()) +
                    " positions");
    if (!uvs.empty() && uvs.size() != positions.size())
        throw Error("mesh has " + std::to_string(uvs.size()) + " uvs for " + std::to_string(positions.size()) +
                    " positions");
    for (std::size_t i = 0; i < triangles.size(); ++i)
        for (std::uint32_t index : triangles[i])
            if (index >= positions.size())
                throw Error("triangle " + std::to_string(i) + ": vertex index " + std::to_string(index) +
                            " out of range (" + std::to_string(positions.size()) + " vertices)");
}

}  // namespace rtlab
