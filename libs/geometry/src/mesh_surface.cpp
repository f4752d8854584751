#include <rtlab/geometry/mesh_surface.hpp>

#include "hit_fill.hpp"

namespace rtlab {

void fill_mesh_hit(const TriangleMesh& mesh, std::uint32_t index, const Ray& ray, float t, float u, float v,
                   const Shape* shape, SurfaceHit& hit) {
    const Point3 &p0 = mesh.corner(index, 0), &p1 = mesh.corner(index, 1), &p2 = mesh.corner(index, 2);
    const float w = 1.0f - u - v;
    const Normal3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    const auto& tri = mesh.triangles[index];
    Vec2 uv(u, v);
    Vec3 dpdu = p1 - p0;
    if (mesh.has_uvs()) {
        const Vec2 &t0 = mesh.uvs[tri[0]], &t1 = mesh.uvs[tri[1]], &t2 = mesh.uvs[tri[2]];
        uv = w * t0 + u * t1 + v * t2;
        // dP/du from the uv parametrisation, when it is not degenerate.
        const Vec2 d1 = t1 - t0, d2 = t2 - t0;
        const float det = d1.x * d2.y - d1.y * d2.x;
        if (det != 0.0f) dpdu = (d2.y * (p1 - p0) - d1.y * (p2 - p0)) / det;
    }
    // Rebuilt from the barycentrics (Pharr et al.): gamma(7) sum |b_i p_i| bounds its distance from the plane.
    const Point3 p = w * p0 + u * p1 + v * p2;
    const Vec3 error = gamma_bound(7) * (glm::abs(w * p0) + glm::abs(u * p1) + glm::abs(v * p2));
    geometry::fill_hit(hit, ray, t, p, error, n, uv, dpdu, index, shape);
    if (mesh.has_normals()) {
        const Normal3 s = w * mesh.normals[tri[0]] + u * mesh.normals[tri[1]] + v * mesh.normals[tri[2]];
        if (glm::dot(s, s) > 0.0f && is_finite(s)) {
            hit.shading_normal = glm::normalize(s);
            const Vec3 tangent = hit.tangent - glm::dot(hit.tangent, hit.shading_normal) * hit.shading_normal;
            if (glm::dot(tangent, tangent) > 0.0f) hit.tangent = glm::normalize(tangent);
        }
    }
}

}  // namespace rtlab
