#pragma once
/// \brief The bunny scene built in code (rtlab-bunny), so that a test can build the same one.
#include <rtlab/geometry/smooth_normals.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>
#include <rtlab/render/render_job.hpp>

#include <memory>
#include <string>
#include <vector>

namespace rtlab::bunny {

/// The default mesh, looked up on the data path.
inline constexpr const char* kDefaultMesh = "models/stanford-bunny.obj";

/// diffuse, phong, mirror, glass.
const std::vector<std::string>& material_names();

/// The mesh's largest extent in the scene.
inline constexpr float kFitSize = 2.0f;

/// The mesh (any PLY or OBJ, scaled so that its largest extent is 2, centred over the origin, standing on
/// the floor at y = 0) as a MeshShape with its kd-tree (SAH), in the material `material` (material_names()),
/// on a grey checkered floor, lit by a point light and an ambient term, classic convention. Throws
/// rtlab::Error for an unknown material (naming the known ones) or an empty mesh.
RenderJob make_bunny_job(std::shared_ptr<const TriangleMesh> mesh, const std::string& material, int width, int height);

}  // namespace rtlab::bunny
