#pragma once
/// \brief A whole mesh as one Shape, intersected through an acceleration structure: the inner trees of
/// a scene's tree of trees (KdShapeTree over MeshShapes and Instances of them).
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/geometry/shape.hpp>

#include <memory>
#include <string_view>

namespace rtlab {

/// \brief A shared mesh and the structure built over it (kd-sah unless told otherwise).
class MeshShape final : public Shape {
public:
    explicit MeshShape(std::shared_ptr<const TriangleMesh> mesh, std::string_view method = "kd-sah",
                       const BuildOptions& options = {});
    AABB bounds() const override { return m_bounds; }
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override { return m_accel->occluded(ray); }
    const TriangleAccelerator& accelerator() const { return *m_accel; }
    /// The options the structure was built with: a scene that gathers small meshes into one tree of its own
    /// (render's Scene) takes only meshes whose triangle test it keeps.
    const BuildOptions& build_options() const { return m_options; }
    /// The triangles, for an area light that samples them by area.
    const TriangleMesh& mesh() const { return *m_mesh; }

private:
    std::shared_ptr<const TriangleMesh> m_mesh;
    std::unique_ptr<TriangleAccelerator> m_accel;
    BuildOptions m_options;
    AABB m_bounds;
};

}  // namespace rtlab
