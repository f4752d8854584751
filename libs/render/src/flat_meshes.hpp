#pragma once
// Small meshes of a scene gathered into one kd-tree over all their triangles (private to render): a scene of
// several meshes of a few triangles each (the Cornell box) otherwise walks one tree per mesh for every ray,
// and pays a root box test and a traversal set-up per mesh for a handful of triangles.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/geometry/surface_hit.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace rtlab {

/// \brief One tree over the triangles of several MeshShapes, each hit reporting the mesh's own object.
class FlatMeshes {
public:
    struct Part {
        const MeshShape* mesh;  // the object's shape: a hit's shape
        std::size_t object;     // the object's index in its scene
    };

    /// Whether a shape can join: a MeshShape of at most max_triangles triangles whose structure is a kd-tree
    /// with the watertight test, so that each triangle's t and barycentrics are the ones its own tree gives.
    static const MeshShape* joinable(const Shape& shape, std::size_t max_triangles);

    /// The parts' triangles in the parts' order; a triangle is found by the same test in the same leaf layout
    /// as in its mesh's own tree.
    explicit FlatMeshes(std::vector<Part> parts);

    /// Closest hit with ray.tmin < t < ray.tmax: t, merged triangle index and barycentrics.
    bool intersect(const Ray& ray, MeshHit& hit) const { return m_accel->intersect(ray, hit); }
    bool occluded(const Ray& ray) const { return m_accel->occluded(ray); }
    /// intersect() and occluded() of a group of rays traced together (TriangleAccelerator's packets).
    void intersect_packet(std::span<const Ray> rays, std::span<MeshHit> hits) const {
        m_accel->intersect_packet(rays, hits);
    }
    void occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
        m_accel->occluded_packet(rays, blocked);
    }
    /// Fills hit as the part's MeshShape::intersect() would have for this triangle hit; returns the object.
    std::size_t complete(const Ray& ray, const MeshHit& found, SurfaceHit& hit) const;

    std::size_t part_count() const { return m_parts.size(); }
    std::size_t triangle_count() const { return m_part_of.size(); }
    std::size_t bytes() const;

private:
    std::vector<Part> m_parts;
    std::vector<std::uint32_t> m_first;    // per part: its first merged triangle
    std::vector<std::uint32_t> m_part_of;  // per merged triangle: its part
    TriangleMesh m_merged;                 // positions and triangles only; the tree's mesh outlives it
    std::unique_ptr<TriangleAccelerator> m_accel;
};

}  // namespace rtlab
