#pragma once
/// \brief Indexed triangle mesh: shared vertex arrays and index triples.
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/math.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rtlab {

/// \brief Triangles as index triples into shared positions, with optional per-vertex normals and uvs
/// (either empty or one per position). Triangle i keeps the index it had in its file (FORMATS.md).
struct TriangleMesh {
    std::vector<Point3> positions;
    std::vector<Normal3> normals;
    std::vector<Vec2> uvs;
    std::vector<std::array<std::uint32_t, 3>> triangles;

    std::size_t triangle_count() const { return triangles.size(); }
    std::size_t vertex_count() const { return positions.size(); }
    bool has_normals() const { return !normals.empty(); }
    bool has_uvs() const { return !uvs.empty(); }

    /// Corner k (0, 1, 2) of triangle i.
    const Point3& corner(std::size_t i, int k) const { return positions[triangles[i][k]]; }
    AABB triangle_bounds(std::size_t i) const;
    AABB bounds() const;
    /// Zero area (repeated or collinear corners) or a non-finite corner.
    bool is_degenerate(std::size_t i) const;
    std::size_t degenerate_count() const;
    /// Throws rtlab::Error when an index is out of range or the optional arrays have the wrong size.
    void validate() const;
};

}  // namespace rtlab
