#include "report.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

namespace rtlab::accel_app {

namespace {

// A figure that does not apply (-1) prints as an empty field.
std::string field(std::int64_t v) { return v < 0 ? "" : std::to_string(v); }
std::string field(double v, const char* format = "{:.6g}") { return v < 0 ? "" : fmt::format(fmt::runtime(format), v); }

void print_table_header() {
    fmt::print("{:<14} {:>9} {:>9} {:>9} {:>6} {:>6} {:>11} {:>6} {:>9} {:<10} {:>9} {:>10} {:>10} {:>10}\n", "method",
               "build_s", "nodes", "leaves", "depth", "leaf", "bytes", "B/tri", "sah", "rays", "count", "closest",
               "any-hit", "mismatch");
}

void print_table_row(const Score& s, const std::string& ray_set) {
    const AccelStats& st = s.stats;
    fmt::print("{:<14} {:>9.4f} {:>9} {:>9} {:>6} {:>6} {:>11} {:>6} {:>9} {:<10} {:>9} {:>10.3f} {:>10.3f} {:>10}\n",
               s.method, s.build_s, field(st.nodes), field(st.leaves), field(st.max_depth),
               field(st.mean_leaf_primitives, "{:.2f}"), field(st.bytes), field(s.bytes_per_triangle, "{:.1f}"),
               field(st.sah_cost, "{:.2f}"), ray_set, s.rays, s.closest_mrays, s.any_mrays, field(s.mismatches));
}

}  // namespace

void print_reference_line(const TriangleAccelerator* reference, std::size_t sample_size) {
    if (reference)
        fmt::print("reference: {} on {} sampled rays per set (watertight test)\n", reference->name(), sample_size);
    else
        fmt::print("reference: none (more than 200k triangles and no Embree): mismatches are not counted\n");
}

void print_footer(int runs, int threads) {
    fmt::print(
        "throughput in Mrays/s, median of {} rounds after one untimed round (the methods take turns in each "
        "round), {} thread(s){}; mismatch = rays whose closest hit differs from the reference on the sample\n",
        runs, threads, threads == 1 ? ", in the tracing thread's CPU time" : ", in wall time");
}

void print_spawn_check(const std::string& method, const SpawnCheck& c, bool sampled) {
    fmt::print("spawned rays{}, {}: {} outward, {} hit their own triangle again; {} inward, {} missed\n",
               sampled ? " (sample)" : "", method, c.outward, c.outward_self_hits, c.inward, c.inward_misses);
}

Report::Report(const std::string& csv_path, RunInfo info) : m_info(std::move(info)) {
    if (!csv_path.empty()) {
        m_csv.emplace(fmt::output_file(csv_path));
        m_csv->print(
            "method,mesh,triangles,threads,build_s,nodes,leaves,empty_leaves,max_depth,mean_leaf_prims,bytes,"
            "sah_cost,ray_set,rays,closest_mrays_s,anyhit_mrays_s,mismatches,triangle_test,reference,"
            "bytes_per_triangle,leaf_width,build_peak_bytes\n");
    }
    print_table_header();
}

void Report::add(const Score& s, const std::string& ray_set, const std::string& reference) {
    print_table_row(s, ray_set);
    if (!m_csv) return;
    const AccelStats& st = s.stats;
    m_csv->print("{},{},{},{},{:.6g},{},{},{},{},{},{},{},{},{},{:.6g},{:.6g},{},{},{},{},{},{}\n", s.method,
                 m_info.mesh_name, m_info.triangles, m_info.threads, s.build_s, field(st.nodes), field(st.leaves),
                 field(st.empty_leaves), field(st.max_depth), field(st.mean_leaf_primitives), field(st.bytes),
                 field(st.sah_cost), ray_set, s.rays, s.closest_mrays, s.any_mrays, field(s.mismatches),
                 m_info.triangle_test, reference, field(s.bytes_per_triangle, "{:.2f}"), field(st.leaf_width),
                 field(st.build_peak_bytes));
}

}  // namespace rtlab::accel_app
