#include <rtlab/geometry/smooth_normals.hpp>

#include <cmath>

namespace rtlab {

TriangleMesh with_smooth_normals(TriangleMesh mesh) {
    if (mesh.has_normals()) return mesh;
    std::vector<Vec3> sum(mesh.positions.size(), Vec3(0.0f));
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
        if (mesh.is_degenerate(i)) continue;
        const Vec3 a = mesh.corner(i, 0), b = mesh.corner(i, 1), c = mesh.corner(i, 2);
        const Vec3 n = glm::cross(b - a, c - a);  // its length is twice the area: the weight
        for (int k = 0; k < 3; ++k) sum[mesh.triangles[i][static_cast<std::size_t>(k)]] += n;
    }
    mesh.normals.resize(sum.size());
    for (std::size_t v = 0; v < sum.size(); ++v) {
        const float len = glm::length(sum[v]);
        // A vertex no triangle uses (the bunny has 1,113) gets any unit normal: nothing interpolates it.
        mesh.normals[v] = len > 0.0f && std::isfinite(len) ? sum[v] / len : Normal3(0.0f, 1.0f, 0.0f);
    }
    return mesh;
}

}  // namespace rtlab
