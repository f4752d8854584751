// The four rendering apps run as a user runs them: the same flags, messages and exit statuses in each, the
// output folder checked before the render, and Ctrl-C (exit status 130, the partial image written).
#include "app_run.hpp"

#include <rtlab/core/image.hpp>
#include <shared_data.hpp>

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace rtlab;
using test::run_app;
namespace fs = std::filesystem;

namespace {

const std::string kWhittedScene = std::string(RTLAB_SOURCE_DIR) + "/scenes/whitted.json";
const std::string kAnalyticScene = std::string(RTLAB_SOURCE_DIR) + "/scenes/analytic.json";

struct App {
    const char* name;
    std::string exe;
    std::string args;  // what the app needs besides the flags (a scene, a mesh)
};

// An octahedron stands in for the bunny so that no data files are needed.
fs::path octahedron(const fs::path& dir) {
    const auto path = dir / "octahedron.obj";
    std::ofstream(path) << "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                           "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
    return path;
}

std::vector<App> apps(const fs::path& dir) {
    return {{"rtlab-render", RENDER_EXE, "'" + kWhittedScene + "'"},
            {"rtlab-whitted", WHITTED_EXE, ""},
            {"rtlab-bunny", BUNNY_EXE, "--mesh '" + octahedron(dir).string() + "'"},
            {"rtlab-solar-system", SOLAR_EXE, "--procedural"}};
}

std::string shell_quoted(const fs::path& path) { return "'" + path.string() + "'"; }

// What the program printed on stdout.
std::string run_stdout(const std::string& exe, const std::string& args, const fs::path& dir) {
    const auto out = dir / "stdout.txt";
    const std::string command = "'" + exe + "' " + args + " > " + shell_quoted(out) + " 2>/dev/null";
    REQUIRE(std::system(command.c_str()) == 0);
    std::ifstream in(out);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Starts `exe args`, sends SIGINT after `delay` and returns the wait status.
int interrupt_after(const std::string& exe, const std::vector<std::string>& args, std::chrono::milliseconds delay) {
    std::vector<char*> argv{const_cast<char*>(exe.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&files, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, exe.c_str(), &files, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    REQUIRE(spawned == 0);
    std::this_thread::sleep_for(delay);
    ::kill(pid, SIGINT);
    int status = 0;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    return status;
}

}  // namespace

TEST_CASE("apps: every app gives the same status and message for the same bad flag", "[apps]") {
    const auto dir = test::scratch_dir("apps_same_flags");
    struct Case {
        const char* flags;
        const char* message;  // after "PROGRAM: "
    };
    const Case cases[] = {
        {"--sspp 4", "unknown option '--sspp'; did you mean '--spp'?"},
        {"--spp 0", "--spp: must be in [1, 65536], not 0"},
        {"--width -5", "--width: must be at least 1, not -5"},
        {"--tonemap bogus", "--tonemap: 'bogus' is not one of none, "},
        {"--threads many", "--threads: expected a whole number, not 'many'"},
        {"--aa none --spp 4", "--spp 4 needs --aa random|jittered|grid|sobol: --aa none takes one sample"},
        {"--aa grid --spp 10", "--spp 10: --aa grid needs a square number of samples per pixel (9 or 16)"},
        {"--depth", "--depth: needs a value"},
    };
    for (const App& app : apps(dir)) {
        for (const Case& c : cases) {
            INFO(app.name << " " << c.flags);
            const auto run = run_app(app.exe, app.args + " -o " + shell_quoted(dir / "x.pfm") + " " + c.flags, dir);
            CHECK(run.status == 2);
            CHECK_THAT(run.err, Catch::Matchers::StartsWith(std::string(app.name) + ": " + c.message));
            CHECK(run.err.find('\n') == run.err.size() - 1);  // one line
        }
    }
}

TEST_CASE("apps: --spp alone keeps the pattern of the scene in rtlab-render and the course apps alike", "[apps]") {
    const auto dir = test::scratch_dir("apps_spp");
    // Both Whitted scenes anti-alias adaptively: --spp alone is refused by both, in the same words.
    const auto file =
        run_app(RENDER_EXE, shell_quoted(kWhittedScene) + " --spp 16 -o " + shell_quoted(dir / "f.pfm"), dir);
    const auto app = run_app(WHITTED_EXE, "--spp 16 -o " + shell_quoted(dir / "a.pfm"), dir);
    CHECK(file.status == 2);
    CHECK(app.status == 2);
    const std::string why = "--spp 16 needs --aa random|jittered|grid|sobol: the scene's anti-aliasing, adaptive,";
    CHECK_THAT(file.err, Catch::Matchers::Contains(why));
    CHECK_THAT(app.err, Catch::Matchers::Contains(why));
    // With a pattern named, both render exactly that many samples: the same image.
    const std::string flags = " --width 24 --height 18 --aa random --spp 3 --threads 2 --quiet -o ";
    REQUIRE(run_app(RENDER_EXE, shell_quoted(kWhittedScene) + flags + shell_quoted(dir / "f.pfm"), dir).status == 0);
    REQUIRE(run_app(WHITTED_EXE, flags + shell_quoted(dir / "a.pfm"), dir).status == 0);
    CHECK(test::same_pixels(read_pfm(dir / "f.pfm"), read_pfm(dir / "a.pfm")));
}

TEST_CASE("apps: rtlab-render keeps the scene after a repeatable option", "[apps]") {
    const auto dir = test::scratch_dir("apps_render_repeatable");
    for (const std::string flag : {"--plugin ./no-such.so", "--plugin=./no-such.so"}) {
        INFO(flag);
        const auto run = run_app(RENDER_EXE, flag + " " + shell_quoted(kWhittedScene), dir);
        CHECK(run.status == 1);  // the plugin file is bad input, the command line is fine
        CHECK_THAT(run.err, Catch::Matchers::Contains("plugin './no-such.so': file not found"));
        CHECK(run.err.find("give a scene file") == std::string::npos);
    }
    const auto out = dir / "x.pfm";
    fs::remove(out);
    const auto run = run_app(RENDER_EXE,
                             "--data-dir " + shell_quoted(dir) + " " + shell_quoted(kWhittedScene) +
                                 " --width 8 --height 6 --quiet -o " + shell_quoted(out),
                             dir);
    CHECK(run.status == 0);
    CHECK(fs::is_regular_file(out));
    const auto none = run_app(RENDER_EXE, "--data-dir " + shell_quoted(dir), dir);
    CHECK(none.status == 2);
    CHECK_THAT(none.err, Catch::Matchers::StartsWith("rtlab-render: give a scene file"));
}

TEST_CASE("apps: every app checks the output folder before rendering and makes a missing last one", "[apps]") {
    const auto dir = test::scratch_dir("apps_output_folder");
    for (const App& app : apps(dir)) {
        INFO(app.name);
        fs::remove_all(dir / "missing");
        fs::remove_all(dir / "made");
        const auto deep = dir / "missing" / "deeper" / "x.pfm";
        const auto bad = run_app(app.exe, app.args + " --width 8 --height 6 --quiet -o " + shell_quoted(deep), dir);
        CHECK(bad.status == 1);
        CHECK_THAT(bad.err, Catch::Matchers::StartsWith(std::string(app.name) + ": " + shell_quoted(deep) +
                                                        ": its folder " + shell_quoted(deep.parent_path()) +
                                                        " does not exist, nor does " + shell_quoted(dir / "missing")));
        CHECK_FALSE(fs::exists(dir / "missing"));
        const auto made = dir / "made" / "x.pfm";
        const auto good = run_app(app.exe, app.args + " --width 8 --height 6 --quiet -o " + shell_quoted(made), dir);
        CHECK(good.status == 0);
        CHECK(fs::is_regular_file(made));
    }
}

TEST_CASE("apps: rtlab-render prints tone parameters in their shortest form and no empty tone line", "[apps]") {
    const auto dir = test::scratch_dir("apps_render_tone");
    const std::string flags = " --width 16 --height 12 --threads 2 -o ";
    const auto png = run_stdout(RENDER_EXE, shell_quoted(kAnalyticScene) + flags + shell_quoted(dir / "a.png"), dir);
    CHECK_THAT(png, Catch::Matchers::Contains("tone: reinhard: key 0.18, L_avg"));
    const auto exr = run_stdout(RENDER_EXE, shell_quoted(kAnalyticScene) + flags + shell_quoted(dir / "a.exr"), dir);
    CHECK_THAT(exr, Catch::Matchers::Contains("tone: reinhard not applied: .exr keeps linear values\n"));
    CHECK(exr.find("tone: \n") == std::string::npos);
}

TEST_CASE("apps: Ctrl-C stops every app with status 130 and writes the partial image", "[apps]") {
    const auto dir = test::scratch_dir("apps_interrupt");
    const auto mesh = octahedron(dir);
    struct Case {
        const char* name;
        std::string exe;
        std::vector<std::string> args;
    };
    // Renders of several seconds on one thread, stopped after a fraction of one.
    const std::vector<std::string> slow{"--width", "400", "--height",  "300", "--aa",    "random",
                                        "--spp",   "64",  "--threads", "1",   "--quiet", "-o"};
    const Case cases[] = {{"rtlab-render", RENDER_EXE, {kWhittedScene}},
                          {"rtlab-whitted", WHITTED_EXE, {}},
                          {"rtlab-bunny", BUNNY_EXE, {"--mesh", mesh.string()}},
                          {"rtlab-solar-system", SOLAR_EXE, {"--procedural"}}};
    for (const Case& c : cases) {
        INFO(c.name);
        const auto out = dir / (std::string(c.name) + ".pfm");
        fs::remove(out);
        std::vector<std::string> args = c.args;
        args.insert(args.end(), slow.begin(), slow.end());
        args.push_back(out.string());
        // The handler is set when the render starts: a signal before that ends the process the usual way (on a
        // busy machine, or under the sanitizers, where the procedural maps take seconds, the start can take
        // longer), so try again later.
        int status = 0;
        for (int delay_ms : {300, 1000, 3000, 10000}) {
            status = interrupt_after(c.exe, args, std::chrono::milliseconds(delay_ms));
            if (!WIFSIGNALED(status)) break;
        }
        REQUIRE(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 130);
        REQUIRE(fs::is_regular_file(out));
        const Image partial = read_pfm(out);
        CHECK(partial.width() == 400);
        CHECK(partial.height() == 300);
    }
}

TEST_CASE("apps: Ctrl-C stops a noise target render and a share render with status 130", "[apps]") {
    const auto dir = test::scratch_dir("apps_interrupt_noise");
    const std::string cornell = std::string(RTLAB_SOURCE_DIR) + "/scenes/cornell_box.json";
    // Renders of many seconds on one thread.
    const std::vector<std::string> slow{cornell, "--width", "96", "--height", "96", "--threads", "1", "--quiet"};
    auto interrupted = [&](std::vector<std::string> args) {
        args.insert(args.begin(), slow.begin(), slow.end());
        int status = 0;
        for (int delay_ms : {300, 1000, 3000, 10000}) {  // as above: the handler is set once the render starts
            status = interrupt_after(RENDER_EXE, args, std::chrono::milliseconds(delay_ms));
            if (!WIFSIGNALED(status)) break;
        }
        REQUIRE(WIFEXITED(status));
        return WEXITSTATUS(status);
    };
    const auto image = dir / "noise.pfm";
    fs::remove(image);
    CHECK(interrupted({"--noise", "1e-5", "--spp", "65536", "-o", image.string()}) == 130);
    CHECK(fs::is_regular_file(image));
    // A share keeps the blocks it finished (none when stopped within the first): whatever it wrote merges.
    const auto share = dir / "stopped.rtshare";
    fs::remove(share);
    CHECK(interrupted({"--sample-range", "0:65536", "-o", share.string()}) == 130);
    if (fs::exists(share)) {
        const auto run = run_app(MERGE_EXE, shell_quoted(share) + " -o " + shell_quoted(dir / "merged.pfm"), dir);
        CHECK(run.status == 0);
    }
    for (const auto& entry : fs::directory_iterator(dir))  // no temporary file left behind
        CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
}
