#pragma once
/// \brief Vertex normals for a mesh that has none (a scanned mesh such as the Stanford bunny).
#include <rtlab/geometry/triangle_mesh.hpp>

namespace rtlab {

/// Area-weighted vertex normals, so that a mesh without normals shades smoothly; a mesh that has normals is
/// returned unchanged. Degenerate triangles add nothing; a vertex no triangle uses gets +y (nothing
/// interpolates it). Used by rtlab-bunny and by the scene loader's mesh key "smooth_normals", so that both
/// shade the same mesh identically.
TriangleMesh with_smooth_normals(TriangleMesh mesh);

}  // namespace rtlab
