#pragma once
// --spawn (FORMATS.md): the secondary rays that leave the surfaces a spawn file names, and how they fared.
#include <rtlab/accel/accelerator.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace rtlab::accel_app {

/// \brief The surfaces spawned rays leave: ray k leaves triangle triangles[k].
struct SpawnSources {
    std::vector<std::int32_t> triangles;  // the spawn file's records
    std::vector<unsigned char> outward;   // 1: leaves on the side of the triangle's geometric normal
};

/// Reads the spawn file of `rays` and spawns, for each ray k, the secondary ray the renderer would: the
/// surface hit at the ray's origin on its triangle (point, geometric normal and error bound rebuilt from the
/// origin's barycentrics, as for a hit found by a ray), then spawn_ray from it along ray k's direction.
/// Throws rtlab::Error naming the spawn file when its count is not the ray file's or a triangle is not in
/// the mesh.
std::vector<Ray> spawn_rays(const TriangleMesh& mesh, std::span<const Ray> rays,
                            const std::filesystem::path& spawn_path, SpawnSources& sources);

/// \brief The spawn file's promise: an outward ray never hits its own triangle again, an inward one hits
/// something.
struct SpawnCheck {
    std::size_t outward = 0, outward_self_hits = 0, inward = 0, inward_misses = 0;
};

/// hits[i] answers spawned ray ray_index[i] (all rays in order when ray_index is empty).
SpawnCheck check_spawned(const SpawnSources& sources, std::span<const MeshHit> hits,
                         std::span<const std::size_t> ray_index);

}  // namespace rtlab::accel_app
