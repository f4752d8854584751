#include "options.hpp"

#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/core/error.hpp>

#include <fmt/format.h>

#include <algorithm>

namespace rtlab::accel_app {

void add_options(CLI::App& app, Options& o) {
    app.add_option("--mesh", o.mesh_path, "mesh file (.ply or .obj)")->required();
    app.add_option("--method", o.methods,
                   fmt::format("{} (repeatable; default: kd-sah, kd-sah-binned, bvh and embree)",
                               fmt::join(accelerator_methods(), ", ")));
    app.add_option("--rays", o.ray_specs, "primary, random or a ray file (repeatable; default: primary and random)");
    app.add_option("--spawn", o.spawn_path,
                   "spawn file (RTSPAWN1) of the one --rays file: trace instead the rays that the library's offset "
                   "routine spawns from each ray's surface; reports outward rays that hit their own triangle again "
                   "and inward rays that miss");
    app.add_option("--threads", o.threads, "threads for building and tracing (default: all)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--runs", o.runs, "timed builds and tracing rounds per method (median; default 5)")
        ->check(CLI::PositiveNumber);
    app.add_option("--hits-out", o.hits_out,
                   "write the closest hits of the first method other than brute on the first ray set (RTHITS01)");
    app.add_option("--csv", o.csv_path, "write the results as CSV (FORMATS.md)");
    app.add_option("--triangle", o.triangle, "ray-triangle test: watertight, moller or plane");
    app.add_option("--leaf-width", o.leaf_width,
                   fmt::format("triangles a kd-tree leaf tests at once: {} (default: the widest)",
                               fmt::join(kd_leaf_widths(), " or ")));
    app.add_option("--sample", o.sample_size, "rays checked against the reference per ray set (default 2000)");
    app.add_option("--primary-size", o.primary_size, "N of the N x N primary set (default 1024)")
        ->check(CLI::PositiveNumber);
    app.add_flag(
        "--packets", o.packets,
        "instead of --rays: trace the primary set in 4 x 2 pixel tiles and shadow rays from its hits towards a "
        "point above the mesh, each method one ray at a time and in packets (the kd-trees' packet walk, "
        "Embree's rtcIntersect8), and count where the packets' answers differ from the single rays'");
    app.add_option("--random-count", o.random_count, "rays in the random set (default 1,000,000)");
}

BuildOptions build_options(const Options& o) {
    BuildOptions options;
    options.triangle_test = parse_triangle_test(o.triangle);
    options.threads = o.threads;
    options.leaf_width = o.leaf_width;
    return options;
}

void complete_options(Options& o) {
    const auto known = accelerator_methods();
    if (o.methods.empty()) {
        o.methods = {"kd-sah", "kd-sah-binned", "bvh"};
        if (std::find(known.begin(), known.end(), "embree") != known.end()) o.methods.emplace_back("embree");
    }
    for (const auto& m : o.methods)
        if (std::find(known.begin(), known.end(), m) == known.end())
            make_accelerator(m, TriangleMesh{});  // throws the listing
    if (o.packets && (!o.ray_specs.empty() || !o.spawn_path.empty()))
        throw Error("--packets traces its own ray sets: give no --rays or --spawn with it");
    if (o.ray_specs.empty())
        o.ray_specs = o.packets ? std::vector<std::string>{"primary"} : std::vector<std::string>{"primary", "random"};
    const bool one_file = o.ray_specs.size() == 1 && o.ray_specs[0] != "primary" && o.ray_specs[0] != "random";
    if (!o.spawn_path.empty() && !one_file)
        throw Error("--spawn " + o.spawn_path + " needs exactly one --rays FILE: the rays whose triangles it lists");
}

}  // namespace rtlab::accel_app
