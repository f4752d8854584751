// rtlab-accel: builds acceleration structures over a mesh and reports build time, size, closest-hit and
// any-hit throughput, and mismatches against a reference (DESIGN.md, FORMATS.md).
#include "options.hpp"
#include "packet_bench.hpp"
#include "ray_sets.hpp"
#include "report.hpp"
#include "scoring.hpp"
#include "timing.hpp"

#include <rtlab/accel/ray_io.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <fmt/core.h>
#include <tbb/task_arena.h>
#include <CLI/CLI.hpp>

#include <exception>
#include <filesystem>

namespace {

using namespace rtlab;
using namespace rtlab::accel_app;

TriangleMesh load_and_describe_mesh(const std::string& path) {
    const auto start = Clock::now();
    TriangleMesh mesh = load_mesh(path);
    fmt::print("mesh {}: {} triangles, {} vertices, loaded in {:.3f} s\n", path, mesh.triangle_count(),
               mesh.vertex_count(), seconds_since(start));
    return mesh;
}

// Each method's answers to the spawned rays against the spawn file's promise (brute force: on the sample).
void report_spawn_checks(const std::vector<Built>& built, const std::vector<Traced>& traced,
                         const SpawnSources& sources, std::size_t sample_size) {
    const std::vector<std::size_t> sample = even_sample(sources.triangles.size(), sample_size);
    for (std::size_t m = 0; m < built.size(); ++m) {
        const bool sampled = built[m].method == "brute";
        print_spawn_check(built[m].method,
                          check_spawned(sources, traced[m].hits, sampled ? sample : std::vector<std::size_t>{}),
                          sampled);
    }
}

void run(Options& o) {
    const BuildOptions build = build_options(o);
    complete_options(o);
    const TriangleMesh mesh = load_and_describe_mesh(o.mesh_path);
    const std::vector<RaySet> sets = make_ray_sets(o, mesh);

    tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
    const int threads = arena.max_concurrency();
    const auto reference = make_reference(mesh, build, arena);
    std::vector<Reference> references;
    for (const RaySet& set : sets)
        references.push_back(reference_answers(reference.get(), set.rays, o.sample_size, arena));
    print_reference_line(reference.get(), references.front().sample.size());

    Report report(o.csv_path, RunInfo{std::filesystem::path(o.mesh_path).filename().string(), mesh.triangle_count(),
                                      threads, std::string(to_string(build.triangle_test))});
    // Every method is built first, then each ray set is traced with all of them in turn.
    const std::vector<Built> built = build_methods(o.methods, mesh, build, o.runs, arena);
    if (o.packets) {
        run_packet_sets(o, mesh, built, reference.get(), report, arena);
        print_footer(o.runs, threads);
        return;
    }
    bool hits_written = false;
    for (std::size_t s = 0; s < sets.size(); ++s) {
        const std::vector<Ray> sampled = sample_rays(sets[s].rays, o.sample_size);
        const std::vector<Traced> traced = trace_in_rounds(built, sets[s].rays, sampled, o.runs, arena);
        for (std::size_t m = 0; m < built.size(); ++m) {
            report.add(score(built[m], traced[m], references[s], mesh), sets[s].name, references[s].name);
            // Brute force traced only the sample, so its records do not answer the whole set.
            if (!o.hits_out.empty() && !hits_written && s == 0 && built[m].method != "brute") {
                write_hit_file(o.hits_out, traced[m].hits);
                hits_written = true;
            }
        }
        if (sets[s].spawned) report_spawn_checks(built, traced, *sets[s].spawned, o.sample_size);
    }
    print_footer(o.runs, threads);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "rtlab-accel: build acceleration structures over a mesh; report build time, size, throughput and "
        "mismatches against a reference"};
    Options options;
    add_options(app, options);
    CLI11_PARSE(app, argc, argv);
    try {
        run(options);
    } catch (const std::exception& e) {
        fmt::print(stderr, "rtlab-accel: {}\n", e.what());
        return 1;
    }
    return 0;
}
