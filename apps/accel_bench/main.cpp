// rtlab-accel: builds acceleration structures over a mesh and reports build time, size, closest-hit and
// any-hit throughput, and mismatches against a reference (DESIGN.md, FORMATS.md).
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/hit_agreement.hpp>
#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/accel/ray_io.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <fmt/format.h>
#include <fmt/os.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace rtlab;
using Clock = std::chrono::steady_clock;

struct RaySet {
    std::string name;
    std::vector<Ray> rays;
};

struct Reference {
    std::string name;                 // "brute" or "embree"
    std::vector<std::size_t> sample;  // indices of the rays it answered
    std::vector<MeshHit> hits;        // hits[k] answers rays[sample[k]]
    std::vector<unsigned char> hit;  // not vector<bool>: filled in parallel, one byte per ray
};

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One pass: every ray traced, each answer written to its record, in parallel blocks.
void trace_closest(const TriangleAccelerator& accel, const std::vector<Ray>& rays, std::vector<MeshHit>& out) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            MeshHit h;
            out[i] = accel.intersect(rays[i], h) ? h : MeshHit{};
        }
    });
}

void trace_any(const TriangleAccelerator& accel, const std::vector<Ray>& rays, std::vector<unsigned char>& out) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) out[i] = accel.occluded(rays[i]) ? 1 : 0;
    });
}

// A method built for the run, and what tracing one ray set with it gave.
struct Built {
    std::string method;
    std::unique_ptr<TriangleAccelerator> accel;
    double build_s = 0;
};

struct Traced {
    const std::vector<Ray>* rays = nullptr;
    std::vector<MeshHit> hits;
    std::vector<unsigned char> blocked;
    std::vector<double> closest_s, any_s;  // one per timed round
};

std::vector<std::size_t> even_sample(std::size_t n, std::size_t count) {
    std::vector<std::size_t> s;
    if (n == 0) return s;
    count = std::min(count, n);
    for (std::size_t k = 0; k < count; ++k) s.push_back(k * n / count);
    return s;
}

std::string field(std::int64_t v) { return v < 0 ? "" : std::to_string(v); }
std::string field(double v, const char* format = "{:.6g}") { return v < 0 ? "" : fmt::format(fmt::runtime(format), v); }

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rtlab-accel: build acceleration structures over a mesh; report build time, size, throughput and "
                 "mismatches against a reference"};
    std::string mesh_path;
    std::vector<std::string> methods;
    std::vector<std::string> ray_specs;
    int threads = 0, runs = 5, primary_size = 1024, leaf_width = 0;
    std::size_t random_count = 1000000, sample_size = 2000;
    std::string hits_out, csv_path, triangle = "watertight";
    app.add_option("--mesh", mesh_path, "mesh file (.ply or .obj)")->required();
    app.add_option("--method", methods,
                   fmt::format("{} (repeatable; default: kd-sah, kd-sah-binned, bvh and embree)",
                               fmt::join(accelerator_methods(), ", ")));
    app.add_option("--rays", ray_specs, "primary, random or a ray file (repeatable; default: primary and random)");
    app.add_option("--threads", threads, "threads for building and tracing (default: all)")->check(CLI::NonNegativeNumber);
    app.add_option("--runs", runs, "timed builds and tracing rounds per method (median; default 5)")->check(CLI::PositiveNumber);
    app.add_option("--hits-out", hits_out,
                   "write the closest hits of the first method other than brute on the first ray set (RTHITS01)");
    app.add_option("--csv", csv_path, "write the results as CSV (FORMATS.md)");
    app.add_option("--triangle", triangle, "ray-triangle test: watertight, moller or plane");
    app.add_option("--leaf-width", leaf_width,
                   fmt::format("triangles a kd-tree leaf tests at once: {} (default: the widest)",
                               fmt::join(kd_leaf_widths(), " or ")));
    app.add_option("--sample", sample_size, "rays checked against the reference per ray set (default 2000)");
    app.add_option("--primary-size", primary_size, "N of the N x N primary set (default 1024)")->check(CLI::PositiveNumber);
    app.add_option("--random-count", random_count, "rays in the random set (default 1,000,000)");
    CLI11_PARSE(app, argc, argv);

    try {
        BuildOptions options;
        options.triangle_test = parse_triangle_test(triangle);
        options.threads = threads;
        options.leaf_width = leaf_width;
        const auto known = accelerator_methods();
        if (methods.empty()) {
            methods = {"kd-sah", "kd-sah-binned", "bvh"};
            if (std::find(known.begin(), known.end(), "embree") != known.end()) methods.emplace_back("embree");
        }
        for (const auto& m : methods)
            if (std::find(known.begin(), known.end(), m) == known.end()) make_accelerator(m, TriangleMesh{});  // throws the listing
        if (ray_specs.empty()) ray_specs = {"primary", "random"};

        const auto load_start = Clock::now();
        const TriangleMesh mesh = load_mesh(mesh_path);
        const AABB bounds = mesh.bounds();
        fmt::print("mesh {}: {} triangles, {} vertices, loaded in {:.3f} s\n", mesh_path, mesh.triangle_count(),
                   mesh.vertex_count(), seconds_since(load_start));

        std::vector<RaySet> sets;
        for (const auto& spec : ray_specs) {
            if (spec == "primary") sets.push_back({"primary", primary_rays(bounds, primary_size)});
            else if (spec == "random") sets.push_back({"random", random_rays(bounds, random_count)});
            else sets.push_back({std::filesystem::path(spec).filename().string(), read_ray_file(spec)});
        }

        tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
        const int thread_count = arena.max_concurrency();

        // The reference: brute force on a sample up to ~200k triangles, else Embree when built with it.
        const bool use_brute = mesh.triangle_count() <= 200000;
        const bool have_embree = std::find(known.begin(), known.end(), "embree") != known.end();
        std::unique_ptr<TriangleAccelerator> reference_accel;
        BuildOptions reference_options = options;
        reference_options.triangle_test = TriangleTest::watertight;
        if (use_brute) reference_accel = make_accelerator("brute", mesh, reference_options);
        else if (have_embree) arena.execute([&] { reference_accel = make_accelerator("embree", mesh, reference_options); });
        std::vector<Reference> references;
        for (const auto& set : sets) {
            Reference ref;
            if (reference_accel) {
                ref.name = std::string(reference_accel->name());
                ref.sample = even_sample(set.rays.size(), sample_size);
                ref.hits.resize(ref.sample.size());
                ref.hit.resize(ref.sample.size());
                arena.execute([&] {
                    tbb::parallel_for(std::size_t{0}, ref.sample.size(), [&](std::size_t k) {
                        MeshHit h;
                        ref.hit[k] = reference_accel->intersect(set.rays[ref.sample[k]], h) ? 1 : 0;
                        ref.hits[k] = h;
                    });
                });
            }
            references.push_back(std::move(ref));
        }
        if (reference_accel)
            fmt::print("reference: {} on {} sampled rays per set (watertight test)\n", reference_accel->name(),
                       references.front().sample.size());
        else
            fmt::print("reference: none (more than 200k triangles and no Embree): mismatches are not counted\n");

        std::optional<fmt::ostream> csv;
        if (!csv_path.empty()) {
            csv.emplace(fmt::output_file(csv_path));
            csv->print("method,mesh,triangles,threads,build_s,nodes,leaves,empty_leaves,max_depth,mean_leaf_prims,bytes,"
                       "sah_cost,ray_set,rays,closest_mrays_s,anyhit_mrays_s,mismatches,triangle_test,reference,"
                       "bytes_per_triangle,leaf_width\n");
        }
        fmt::print("{:<14} {:>9} {:>9} {:>9} {:>6} {:>6} {:>11} {:>6} {:>9} {:<10} {:>9} {:>10} {:>10} {:>10}\n", "method",
                   "build_s", "nodes", "leaves", "depth", "leaf", "bytes", "B/tri", "sah", "rays", "count", "closest",
                   "any-hit", "mismatch");
        const std::string mesh_name = std::filesystem::path(mesh_path).filename().string();
        bool hits_written = false;
        // Every method is built first (build time: median of the runs, one build kept for tracing) ...
        std::vector<Built> built;
        for (const auto& method : methods) {
            Built b;
            b.method = method;
            std::vector<double> build_times;
            const int build_runs = (method == "brute" || method == "kd-sah-naive") ? 1 : runs;
            for (int k = 0; k < build_runs; ++k) {
                const auto start = Clock::now();
                arena.execute([&] { b.accel = make_accelerator(method, mesh, options); });
                build_times.push_back(seconds_since(start));
            }
            b.build_s = median(build_times);
            built.push_back(std::move(b));
        }

        // ... then each ray set is traced in rounds, each round timing one closest-hit and one any-hit pass of
        // every method in turn: a slow spell of these shared machines then falls on all methods alike, and
        // the ratios between methods of one run hold even when the absolute figures drift.
        for (std::size_t s = 0; s < sets.size(); ++s) {
            const RaySet& set = sets[s];
            const Reference& ref = references[s];
            // Brute force traces only the reference sample: a full pass would take hours.
            std::vector<Ray> sampled;
            for (std::size_t i : even_sample(set.rays.size(), sample_size)) sampled.push_back(set.rays[i]);
            std::vector<Traced> traced(built.size());
            for (std::size_t m = 0; m < built.size(); ++m) {
                const std::vector<Ray>& rays = built[m].method == "brute" ? sampled : set.rays;
                traced[m].rays = &rays;
                traced[m].hits.resize(rays.size());
                traced[m].blocked.resize(rays.size());
            }
            arena.execute([&] {
                for (int round = -1; round < runs; ++round) {  // round -1: the untimed warm-up
                    for (std::size_t m = 0; m < built.size(); ++m) {
                        Traced& t = traced[m];
                        const auto start = Clock::now();
                        trace_closest(*built[m].accel, *t.rays, t.hits);
                        const auto middle = Clock::now();
                        trace_any(*built[m].accel, *t.rays, t.blocked);
                        if (round < 0) continue;
                        t.closest_s.push_back(std::chrono::duration<double>(middle - start).count());
                        t.any_s.push_back(seconds_since(middle));
                    }
                }
            });
            for (std::size_t m = 0; m < built.size(); ++m) {
                const std::string& method = built[m].method;
                const Traced& t = traced[m];
                const AccelStats st = built[m].accel->stats();
                // The structure's own bytes (nodes, indices, leaf layouts) per triangle of the mesh.
                const double bytes_per_triangle =
                    st.bytes < 0 || mesh.triangle_count() == 0 ? -1.0
                                                               : static_cast<double>(st.bytes) / static_cast<double>(mesh.triangle_count());
                std::int64_t mismatches = -1;
                if (!ref.sample.empty()) {
                    mismatches = 0;
                    for (std::size_t k = 0; k < ref.sample.size(); ++k) {
                        const std::size_t i = method == "brute" ? k : ref.sample[k];
                        mismatches += !same_hit(t.hits[i].hit(), t.hits[i], ref.hit[k] != 0, ref.hits[k]);
                    }
                }
                const std::size_t count = t.rays->size();
                const double closest_mrays = static_cast<double>(count) / median(t.closest_s) / 1e6;
                const double any_mrays = static_cast<double>(count) / median(t.any_s) / 1e6;
                fmt::print("{:<14} {:>9.4f} {:>9} {:>9} {:>6} {:>6} {:>11} {:>6} {:>9} {:<10} {:>9} {:>10.3f} {:>10.3f} {:>10}\n",
                           method, built[m].build_s, field(st.nodes), field(st.leaves), field(st.max_depth),
                           field(st.mean_leaf_primitives, "{:.2f}"), field(st.bytes), field(bytes_per_triangle, "{:.1f}"),
                           field(st.sah_cost, "{:.2f}"), set.name, count, closest_mrays, any_mrays, field(mismatches));
                if (csv)
                    csv->print("{},{},{},{},{:.6g},{},{},{},{},{},{},{},{},{},{:.6g},{:.6g},{},{},{},{},{}\n", method, mesh_name,
                               mesh.triangle_count(), thread_count, built[m].build_s, field(st.nodes), field(st.leaves),
                               field(st.empty_leaves), field(st.max_depth), field(st.mean_leaf_primitives), field(st.bytes),
                               field(st.sah_cost), set.name, count, closest_mrays, any_mrays, field(mismatches),
                               to_string(options.triangle_test), ref.name, field(bytes_per_triangle, "{:.2f}"),
                               field(st.leaf_width));
                // Brute force traced only the sample, so its records do not answer the whole set.
                if (!hits_out.empty() && !hits_written && s == 0 && method != "brute") {
                    write_hit_file(hits_out, t.hits);
                    hits_written = true;
                }
            }
        }
        fmt::print("throughput in Mrays/s, median of {} rounds after one untimed round (the methods take turns in each "
                   "round), {} thread(s); mismatch = rays whose closest hit differs from the reference on the sample\n",
                   runs, thread_count);
    } catch (const std::exception& e) {
        fmt::print(stderr, "rtlab-accel: {}\n", e.what());
        return 1;
    }
    return 0;
}
