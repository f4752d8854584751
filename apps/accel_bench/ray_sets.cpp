#include "ray_sets.hpp"

#include "options.hpp"

#include <rtlab/accel/ray_io.hpp>

#include <filesystem>

namespace rtlab::accel_app {

std::vector<RaySet> make_ray_sets(const Options& o, const TriangleMesh& mesh) {
    const AABB bounds = mesh.bounds();
    std::vector<RaySet> sets;
    for (const auto& spec : o.ray_specs) {
        if (spec == "primary")
            sets.push_back({"primary", primary_rays(bounds, o.primary_size), std::nullopt});
        else if (spec == "random")
            sets.push_back({"random", random_rays(bounds, o.random_count), std::nullopt});
        else
            sets.push_back({std::filesystem::path(spec).filename().string(), read_ray_file(spec), std::nullopt});
    }
    if (!o.spawn_path.empty()) {
        RaySet& set = sets.front();
        set.spawned.emplace();
        set.rays = spawn_rays(mesh, set.rays, o.spawn_path, *set.spawned);
    }
    return sets;
}

}  // namespace rtlab::accel_app
