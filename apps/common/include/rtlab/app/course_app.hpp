#pragma once
/// \brief What the course apps (rtlab-whitted, rtlab-solar-system, rtlab-bunny) share: one set of command-line
/// flags, the data search path, and running a render job to a file with the progress bar and Ctrl-C.
#include <rtlab/app/command_line.hpp>
#include <rtlab/core/data_path.hpp>
#include <rtlab/render/render_job.hpp>

#include <filesystem>
#include <functional>
#include <string>

namespace rtlab::app {

/// The course apps' flags are the common ones (command_line.hpp); course_data_path reads their --data-dir.
using CourseOptions = CommonOptions;

/// Adds the common flags to a course app's command line, with the built-in tone operators for --tonemap.
/// Set options.output, width and height to the app's defaults first.
void add_course_options(CommandLine& cli, CourseOptions& options);

/// Overrides the job's render settings (pattern, spp, adaptive settings, seed, threads) and Whitted depth with
/// the flags given, and checks that --spp gives exactly that many samples in the resulting pattern
/// (check_sampling: UsageError otherwise).
void apply_course_options(const CourseOptions& options, RenderJob& job);

/// The data path of a course app (rtlab::DataPath::from_environment): every --data-dir, RTLAB_DATA_PATH,
/// RTLAB_SHARED_DIR and the ../shared beside the checkout the executable was built in (neither when
/// RTLAB_NO_SHARED=1), then the files of the Debian data packages (data/assets.tsv). A file is looked up by the
/// name the app gives ("textures/earth.jpg"), so each folder is a data root. Prints one warning line on stderr
/// for each --data-dir or RTLAB_DATA_PATH folder that does not exist ("PROGRAM: warning: --data-dir '/x' does
/// not exist").
DataPath course_data_path(const CourseOptions& options, const std::filesystem::path& executable, const char* program);
/// The same for any app (rtlab-render): its --data-dir folders, the executable, and the name its warnings start with.
DataPath app_data_path(const std::vector<std::filesystem::path>& data_dirs, const std::filesystem::path& executable,
                       const char* program);

/// The running executable's path (/proc/self/exe), or `argv0` when that cannot be read.
std::filesystem::path executable_path(const char* argv0);

/// \brief What run_course_render reports.
struct CourseRenderResult {
    RenderStats stats;
    /// Processor seconds the process spent in the render, all threads together (std::clock): on a machine
    /// shared with other work this says what the render cost, where stats.seconds also counts the waiting.
    double cpu_seconds = 0.0;
    double write_seconds = 0.0;  ///< tone mapping, encoding and writing the output file
    bool interrupted = false;
};

/// Renders `job` with the progress bar (stderr, a terminal, not --quiet) and Ctrl-C as "stop and write what
/// is done", writes `output` with write_render_output (PNG through --tonemap, else linear), and prints one
/// summary line to stdout unless quiet ("whitted: 640x480 in 1.23 s (2.40 CPU s), 1.62 Mrays/s (...) -> OUT (written in
/// 0.05 s)"; scripts/peer-povray.sh reads both times). `label` starts the summary ("whitted", "solar frame 3").
/// The output's folder is made ready first (prepare_output); an app calls that before its own slow work too.
CourseRenderResult run_course_render(const RenderJob& job, const CourseOptions& options,
                                     const std::filesystem::path& output, const std::string& label);

/// Runs `body` inside a oneTBB arena of `threads` threads (0: every core), so that the parallel work of building
/// a scene (the kd-tree of a mesh) honours --threads as the render does: `--threads 1` is one thread from start
/// to finish, not one thread for the render after a build on every core.
void run_with_threads(int threads, const std::function<void()>& body);

}  // namespace rtlab::app
