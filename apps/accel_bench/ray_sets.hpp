#pragma once
// The ray sets rtlab-accel traces: the standard ones of FORMATS.md and ray files.
#include "spawned_rays.hpp"

#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rtlab::accel_app {

struct Options;

struct RaySet {
    std::string name;  // "primary", "random" or the ray file's name
    std::vector<Ray> rays;
    std::optional<SpawnSources> spawned;  // with --spawn: the surfaces the rays leave
};

/// One set per --rays, in order; with --spawn, the rays spawned from the ray file's.
std::vector<RaySet> make_ray_sets(const Options& options, const TriangleMesh& mesh);

}  // namespace rtlab::accel_app
