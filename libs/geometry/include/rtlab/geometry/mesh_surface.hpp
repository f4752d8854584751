#pragma once
/// \brief The surface record of a hit on a mesh triangle, from its t and barycentrics.
#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/surface_hit.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

namespace rtlab {

/// Fills hit for triangle `index` hit at t with barycentrics (u, v): point, geometric normal (winding),
/// shading normal (interpolated vertex normals when the mesh has them), uv (interpolated vertex uvs, else
/// (u, v)) and a tangent along dP/du. Shared by TriangleShape and the accelerated mesh shapes.
void fill_mesh_hit(const TriangleMesh& mesh, std::uint32_t index, const Ray& ray, float t, float u, float v,
                   const Shape* shape, SurfaceHit& hit);

}  // namespace rtlab
