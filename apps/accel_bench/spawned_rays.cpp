#include "spawned_rays.hpp"

#include <rtlab/accel/ray_io.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/geometry/mesh_surface.hpp>
#include <rtlab/geometry/spawn.hpp>

#include <algorithm>
#include <string>

namespace rtlab::accel_app {

namespace {

// The barycentrics (u, v) of the point of triangle (p0, p1, p2) nearest to p, which lies on it up to the
// rounding of whoever wrote the file: least squares in double, then clamped into the triangle, as a
// renderer's hit never lies outside it. A degenerate triangle gives (0, 0).
Vec2 barycentrics(const Point3& p, const Point3& p0, const Point3& p1, const Point3& p2) {
    const glm::dvec3 e1 = glm::dvec3(p1) - glm::dvec3(p0), e2 = glm::dvec3(p2) - glm::dvec3(p0);
    const glm::dvec3 q = glm::dvec3(p) - glm::dvec3(p0);
    const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
    const double det = a * c - b * b;
    if (!(det > 0.0)) return Vec2(0.0f);
    const double r1 = glm::dot(q, e1), r2 = glm::dot(q, e2);
    double u = std::max(0.0, (c * r1 - b * r2) / det), v = std::max(0.0, (a * r2 - b * r1) / det);
    if (u + v > 1.0) {
        const double sum = u + v;
        u /= sum;
        v /= sum;
    }
    return Vec2(static_cast<float>(u), static_cast<float>(v));
}

std::vector<std::int32_t> read_spawn_triangles(const std::filesystem::path& path, std::size_t rays,
                                               std::size_t triangles) {
    std::vector<std::int32_t> own = read_spawn_file(path);
    if (own.size() != rays)
        throw Error(file_error_message(path, "spawn file of " + std::to_string(own.size()) +
                                                 " records for a ray file of " + std::to_string(rays) + " rays"));
    for (std::size_t k = 0; k < own.size(); ++k)
        if (own[k] < 0 || static_cast<std::size_t>(own[k]) >= triangles)
            throw Error(file_error_message(path, "record " + std::to_string(k) + ": triangle " +
                                                     std::to_string(own[k]) + " is not in the mesh (" +
                                                     std::to_string(triangles) + " triangles)"));
    return own;
}

}  // namespace

std::vector<Ray> spawn_rays(const TriangleMesh& mesh, std::span<const Ray> rays,
                            const std::filesystem::path& spawn_path, SpawnSources& sources) {
    sources.triangles = read_spawn_triangles(spawn_path, rays.size(), mesh.triangle_count());
    sources.outward.clear();
    std::vector<Ray> spawned;
    spawned.reserve(rays.size());
    for (std::size_t k = 0; k < rays.size(); ++k) {
        const auto index = static_cast<std::uint32_t>(sources.triangles[k]);
        const Ray& ray = rays[k];
        const Vec2 uv = barycentrics(ray.origin, mesh.corner(index, 0), mesh.corner(index, 1), mesh.corner(index, 2));
        SurfaceHit hit;
        fill_mesh_hit(mesh, index, ray, 0.0f, uv.x, uv.y, nullptr, hit);
        spawned.push_back(spawn_ray(hit, ray.direction));
        // The side spawn_ray offsets the origin to.
        sources.outward.push_back(glm::dot(ray.direction, hit.geometric_normal) >= 0.0f ? 1 : 0);
    }
    return spawned;
}

SpawnCheck check_spawned(const SpawnSources& sources, std::span<const MeshHit> hits,
                         std::span<const std::size_t> ray_index) {
    SpawnCheck check;
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const std::size_t k = ray_index.empty() ? i : ray_index[i];
        if (sources.outward[k]) {
            ++check.outward;
            check.outward_self_hits +=
                hits[i].hit() && hits[i].primitive == static_cast<std::uint32_t>(sources.triangles[k]);
        } else {
            ++check.inward;
            check.inward_misses += !hits[i].hit();
        }
    }
    return check;
}

}  // namespace rtlab::accel_app
