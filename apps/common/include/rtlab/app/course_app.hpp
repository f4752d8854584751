#pragma once
/// \brief What the course apps (rtlab-whitted, rtlab-solar-system, rtlab-bunny) share: one set of command-line
/// flags, the data search path, and running a render job to a file with the progress bar and Ctrl-C.
#include <rtlab/core/data_path.hpp>
#include <rtlab/render/render_job.hpp>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::app {

/// \brief The flags every course app accepts. Unset optionals keep the scene's own choice (the Whitted
/// scene's adaptive anti-aliasing, say).
struct CourseOptions {
    std::filesystem::path output;  ///< -o; each app sets its default before add_course_options
    int width = 640;
    int height = 480;
    std::optional<std::string> aa;  ///< none, grid, random, jittered, adaptive
    std::optional<int> spp;
    std::optional<float> threshold;  ///< adaptive: colour difference that splits a square
    std::optional<int> aa_depth;     ///< adaptive: subdivision depth
    std::optional<int> max_depth;    ///< Whitted recursion depth
    int threads = 0;
    std::uint64_t seed = 0;
    std::string tonemap = "none";
    bool quiet = false;
    std::vector<std::filesystem::path> data_dirs;
};

/// Adds -o, --width, --height, --aa, --spp, --aa-threshold, --aa-depth, --depth, --threads, --seed, --tonemap,
/// --quiet and --data-dir to `app`, bound to `options`.
void add_course_options(CLI::App& app, CourseOptions& options);

/// Parses the command line. Returns nothing when the app should go on; else the exit status: 0 after --help,
/// 1 after a bad flag (CLI11's message and a hint to --help on stderr), as every rtlab app does.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv);

/// Overrides the job's render settings (pattern, spp, adaptive settings, seed, threads) and Whitted depth with
/// the flags given. Throws rtlab::Error for an unknown --aa name, or --spp, --depth out of range.
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
CourseRenderResult run_course_render(const RenderJob& job, const CourseOptions& options,
                                     const std::filesystem::path& output, const std::string& label);

/// Runs `body` inside a oneTBB arena of `threads` threads (0: every core), so that the parallel work of building
/// a scene (the kd-tree of a mesh) honours --threads as the render does: `--threads 1` is one thread from start
/// to finish, not one thread for the render after a build on every core.
void run_with_threads(int threads, const std::function<void()>& body);

/// The body of a course app's main: runs `body` and returns its status; an exception becomes
/// "NAME: message" on stderr and exit status 1.
int run_app(const char* name, const std::function<int()>& body);

}  // namespace rtlab::app
