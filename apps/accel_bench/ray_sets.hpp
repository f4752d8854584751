#pragma once
// The ray sets rtlab-accel traces: the standard ones of FORMATS.md and ray files.
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/ray.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace rtlab::accel_app {

struct Options;

struct RaySet {
    std::string name;  // "primary", "random" or the ray file's name
    std::vector<Ray> rays;
};

/// One set per --rays, in order.
std::vector<RaySet> make_ray_sets(const Options& options, const AABB& bounds);

}  // namespace rtlab::accel_app
