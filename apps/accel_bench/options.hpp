#pragma once
// rtlab-accel's command line: what it asks for, and the defaults filled in once the mesh is known to load.
#include <rtlab/accel/accelerator.hpp>

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace rtlab::accel_app {

struct Options {
    std::string mesh_path;
    std::vector<std::string> methods;
    std::vector<std::string> ray_specs;  // "primary", "random" or a ray file
    std::string spawn_path;              // with one ray file: the triangle each ray starts on
    int threads = 0, runs = 5, primary_size = 1024, leaf_width = 0;
    std::size_t random_count = 1000000, sample_size = 2000;
    std::string hits_out, csv_path, triangle = "watertight";
    bool packets = false;  // --packets: the coherent sets, singly and in 4 x 2 packets
};

void add_options(CLI::App& app, Options& options);

/// The builders' options; throws rtlab::Error for an unknown triangle test.
BuildOptions build_options(const Options& options);

/// Fills in the default methods and ray sets; throws rtlab::Error listing the known methods for an unknown
/// one, and for --spawn without exactly one ray file.
void complete_options(Options& options);

}  // namespace rtlab::accel_app
