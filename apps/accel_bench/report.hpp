#pragma once
// rtlab-accel's printed table and its CSV file (columns as FORMATS.md lists them, then its own).
#include "scoring.hpp"
#include "spawned_rays.hpp"

#include <fmt/os.h>

#include <optional>
#include <string>

namespace rtlab::accel_app {

/// What every row of one run shares.
struct RunInfo {
    std::string mesh_name;
    std::size_t triangles = 0;
    int threads = 0;
    std::string triangle_test;
};

void print_reference_line(const TriangleAccelerator* reference, std::size_t sample_size);
void print_footer(int runs, int threads);
/// One method's SpawnCheck (`sampled`: on the reference sample only).
void print_spawn_check(const std::string& method, const SpawnCheck& check, bool sampled);

/// \brief The table on stdout and, when a path is given, the CSV file: both headers on construction, then
/// one row per (method, ray set).
class Report {
public:
    Report(const std::string& csv_path, RunInfo info);
    void add(const Score& score, const std::string& ray_set, const std::string& reference);

private:
    RunInfo m_info;
    std::optional<fmt::ostream> m_csv;
};

}  // namespace rtlab::accel_app
