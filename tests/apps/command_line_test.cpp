// The command-line layer every app uses (apps/common command_line.hpp), in-process: values, checks and their
// messages, repeatable options, unknown flags, the sampling rules and the output folder.
#include <rtlab/app/command_line.hpp>
#include <shared_data.hpp>

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

using namespace rtlab;
using namespace rtlab::app;

namespace {

struct Parsed {
    std::optional<int> status;
    std::string err;  // what parse printed on stderr
};

// Parses `args` after the program name, capturing stderr.
Parsed parse(CommandLine& cli, const std::vector<std::string>& args) {
    std::vector<const char*> argv{"prog"};
    for (const auto& a : args) argv.push_back(a.c_str());
    std::fflush(stderr);
    std::FILE* capture = std::tmpfile();
    REQUIRE(capture);
    const int saved = ::dup(STDERR_FILENO);
    REQUIRE(::dup2(::fileno(capture), STDERR_FILENO) >= 0);
    Parsed out;
    out.status = cli.parse(static_cast<int>(argv.size()), argv.data());
    std::fflush(stderr);
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    std::rewind(capture);
    char buffer[4096] = {};
    out.err.assign(buffer, std::fread(buffer, 1, sizeof buffer - 1, capture));
    std::fclose(capture);
    return out;
}

// A course app's command line: defaults 640x480 and out.png.
struct CourseLine {
    CommonOptions o;
    CommandLine cli{"prog", "a test program"};
    CourseLine() {
        o.output = "out.png";
        o.width = 640;
        o.height = 480;
        cli.add_common(o, {"reinhard", "ward"});
    }
};

std::size_t count(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("command line: every common flag reaches its option", "[app]") {
    CourseLine line;
    const auto p = parse(
        line.cli,
        {"-o",        "x.exr", "--width", "320",        "--height",  "200",         "--aa",   "grid",
         "--spp",     "16",    "--depth", "3",          "--threads", "2",           "--seed", "18446744073709551615",
         "--tonemap", "ward",  "-q",      "--data-dir", "a",         "--data-dir=b"});
    REQUIRE_FALSE(p.status);
    CHECK(p.err.empty());
    const CommonOptions& o = line.o;
    CHECK(o.output == "x.exr");
    CHECK(o.width == 320);
    CHECK(o.height == 200);
    CHECK(o.aa == "grid");
    CHECK(o.spp == 16);
    CHECK(o.max_depth == 3);
    CHECK(o.threads == 2);
    CHECK(o.seed == 18446744073709551615ull);
    CHECK(o.tonemap == "ward");
    CHECK(o.quiet);
    CHECK(o.data_dirs == std::vector<std::filesystem::path>{"a", "b"});

    CourseLine adaptive;
    REQUIRE_FALSE(parse(adaptive.cli, {"--aa", "adaptive", "--aa-threshold", "0.1", "--aa-depth", "2"}).status);
    CHECK(adaptive.o.aa_threshold == 0.1f);
    CHECK(adaptive.o.aa_depth == 2);
    // A flag given twice takes the last value, as in most Unix tools.
    CourseLine twice;
    REQUIRE_FALSE(parse(twice.cli, {"--aa", "random", "--spp", "4", "--spp", "9"}).status);
    CHECK(twice.o.spp == 9);
    // Nothing given: the defaults, and nothing that would override a scene.
    CourseLine none;
    REQUIRE_FALSE(parse(none.cli, {}).status);
    CHECK(none.o.output == "out.png");
    CHECK(none.o.width == 640);
    CHECK(none.o.height == 480);
    CHECK_FALSE(none.o.aa);
    CHECK_FALSE(none.o.spp);
    CHECK_FALSE(none.o.seed);
    CHECK_FALSE(none.o.tonemap);
}

TEST_CASE("command line: one image side alone keeps the default aspect ratio and both fit the pixel limit", "[app]") {
    CourseLine wide;
    REQUIRE_FALSE(parse(wide.cli, {"--width", "320"}).status);
    CHECK(wide.o.height == 240);
    CourseLine tall;
    REQUIRE_FALSE(parse(tall.cli, {"--height", "48"}).status);
    CHECK(tall.o.width == 64);
    CourseLine huge;
    const auto p = parse(huge.cli, {"--width", "16384", "--height", "16384"});
    CHECK(p.status == kExitUsage);
    CHECK(p.err == "prog: --width/--height: 16384x16384 is more than 67108864 pixels\n");
    CourseLine side;
    const auto q = parse(side.cli, {"--height", "16384"});
    CHECK(q.status == kExitUsage);
    CHECK(q.err == "prog: --width/--height: 21845x16384 (the default's aspect ratio) is more than 16384 a side\n");
    // Without defaults (rtlab-render: the scene's size) one side alone stays alone.
    CommonOptions o;
    CommandLine cli("prog", "");
    cli.add_common(o, {});
    REQUIRE_FALSE(parse(cli, {"--width", "100"}).status);
    CHECK(o.width == 100);
    CHECK_FALSE(o.height);
}

TEST_CASE("command line: a bad value is one message naming the program and the flag with exit status 2", "[app]") {
    struct Case {
        std::vector<std::string> args;
        const char* message;
    };
    const Case cases[] = {
        {{"--spp", "0"}, "prog: --spp: must be in [1, 65536], not 0\n"},
        {{"--spp", "many"}, "prog: --spp: expected a whole number, not 'many'\n"},
        {{"--spp", "4.5"}, "prog: --spp: expected a whole number, not '4.5'\n"},
        {{"--width", "-5"}, "prog: --width: must be at least 1, not -5\n"},
        {{"--height", "20000"}, "prog: --height: must be at most 16384, not 20000\n"},
        {{"--threads", "-1"}, "prog: --threads: must be in [0, 1024], not -1\n"},
        {{"--aa", "adaptive", "--aa-threshold", "nan"}, "prog: --aa-threshold: expected a number, not 'nan'\n"},
        {{"--seed", "-1"}, "prog: --seed: expected a whole number in [0, 2^64 - 1], not '-1'\n"},
        {{"--aa", "jitered"},
         "prog: --aa: 'jitered' is not one of none, grid, random, jittered, adaptive; did you mean 'jittered'?\n"},
        {{"--tonemap", "bogus"}, "prog: --tonemap: 'bogus' is not one of none, reinhard, ward\n"},
        {{"-o", "out.tiff"}, "prog: -o: 'out.tiff': unknown image format '.tiff'; known: .png, .hdr, .pfm, .exr\n"},
        {{"--sspp", "4"}, "prog: unknown option '--sspp'; did you mean '--spp'?\n"},
        {{"--sspp=4"}, "prog: unknown option '--sspp'; did you mean '--spp'?\n"},
        {{"--frobnicate"}, "prog: unknown option '--frobnicate'\n"},
        {{"stray"}, "prog: unexpected argument 'stray'\n"},
        {{"--width"}, "prog: --width: needs a value\n"},
        {{"--width", "--height", "4"}, "prog: --width: needs a value\n"},
    };
    for (const Case& c : cases) {
        INFO(c.args.front() << " " << (c.args.size() > 1 ? c.args[1] : ""));
        CourseLine line;
        const auto p = parse(line.cli, c.args);
        CHECK(p.status == kExitUsage);
        CHECK(p.err == c.message);
    }
    // The operators are listed once (CLI11's own check listed them twice).
    CourseLine line;
    CHECK(count(parse(line.cli, {"--tonemap", "bogus"}).err, "reinhard") == 1);
    // --help is no error.
    CourseLine help;
    CHECK(parse(help.cli, {"--help"}).status == kExitDone);
}

TEST_CASE("command line: a repeatable option takes one value each time and leaves the positional alone", "[app]") {
    for (const std::vector<std::string>& args : {std::vector<std::string>{"--plugin", "./x.so", "scene.json"},
                                                 {"--plugin=./x.so", "scene.json"},
                                                 {"--plugin", "./x.so", "--plugin", "y.so", "scene.json"},
                                                 {"scene.json", "--plugin", "./x.so"}}) {
        INFO(args.front() << " ... " << args.back());
        CommonOptions o;
        std::vector<std::filesystem::path> plugins;
        std::string scene;
        CommandLine cli("prog", "");
        cli.add_positional("scene", scene, "the scene");
        cli.add_common(o, {});
        cli.add_list("--plugin", plugins, "a plugin");
        const auto p = parse(cli, args);
        REQUIRE_FALSE(p.status);
        CHECK(scene == "scene.json");
        REQUIRE_FALSE(plugins.empty());
        CHECK(plugins.front() == "./x.so");
        CHECK(plugins.size() == (args.size() == 5 ? 2u : 1u));
    }
    CommonOptions o;
    std::string scene;
    CommandLine cli("prog", "");
    cli.add_positional("scene", scene, "the scene");
    cli.add_common(o, {});
    REQUIRE_FALSE(parse(cli, {"--data-dir", "D", "scene.json"}).status);
    CHECK(scene == "scene.json");
    CHECK(o.data_dirs == std::vector<std::filesystem::path>{"D"});
}

TEST_CASE("command line: --spp is exactly N samples in the pattern of --aa or the scene", "[app]") {
    auto settings = [](PixelPattern pattern, int spp) {
        RenderSettings s;
        s.pattern = pattern;
        s.spp = spp;
        return s;
    };
    CommonOptions spp16;
    spp16.spp = 16;
    // The scene's pattern is kept: --spp alone never switches it.
    CHECK_NOTHROW(check_sampling(settings(PixelPattern::random, 16), spp16));
    CHECK_NOTHROW(check_sampling(settings(PixelPattern::jittered, 16), spp16));
    CHECK_THROWS_WITH(check_sampling(settings(PixelPattern::none, 16), spp16),
                      Catch::StartsWith("--spp 16 needs --aa random|jittered|grid: the scene's anti-aliasing, none,"));
    CHECK_THROWS_WITH(check_sampling(settings(PixelPattern::adaptive, 16), spp16),
                      Catch::StartsWith("--spp 16 needs --aa random|jittered|grid: the scene's anti-aliasing, "
                                        "adaptive, picks its samples itself"));
    CommonOptions spp10;
    spp10.spp = 10;
    CHECK_NOTHROW(check_sampling(settings(PixelPattern::random, 10), spp10));
    for (PixelPattern square : {PixelPattern::grid, PixelPattern::jittered})
        CHECK_THROWS_WITH(check_sampling(settings(square, 10), spp10),
                          Catch::Contains("needs a square number of samples per pixel (9 or 16)"));
    // --aa grid with the scene's non-square count says which counts would do.
    CommonOptions grid;
    grid.aa = "grid";
    CHECK_THROWS_WITH(check_sampling(settings(PixelPattern::grid, 5), grid),
                      "--aa grid needs a square number of samples per pixel, and the scene asks for 5: give --spp 4 "
                      "or 9");
    // One sample needs no pattern; the scene's own values are the scene's business.
    CommonOptions one;
    one.spp = 1;
    CHECK_NOTHROW(check_sampling(settings(PixelPattern::none, 1), one));
    CHECK_NOTHROW(check_sampling(settings(PixelPattern::grid, 5), CommonOptions{}));
    // The adaptive settings apply to adaptive only.
    CommonOptions depth;
    depth.aa_depth = 2;
    CHECK_NOTHROW(check_sampling(settings(PixelPattern::adaptive, 1), depth));
    CHECK_THROWS_AS(check_sampling(settings(PixelPattern::random, 4), depth), UsageError);

    // Through the command line, the checks that need no scene come at once.
    CourseLine line;
    const auto p = parse(line.cli, {"--aa", "jittered", "--spp", "8"});
    CHECK(p.status == kExitUsage);
    CHECK(p.err ==
          "prog: --spp 8: --aa jittered needs a square number of samples per pixel (4 or 9); --aa random "
          "takes any number\n");
}

TEST_CASE("command line: the output folder is made ready before any work or refused", "[app]") {
    namespace fs = std::filesystem;
    const auto dir = test::scratch_dir("command_line_output");
    fs::remove_all(dir / "new");
    fs::remove_all(dir / "missing");
    CHECK_NOTHROW(prepare_output("bare.png"));     // the current folder
    CHECK_NOTHROW(prepare_output(dir / "x.png"));  // an existing folder
    // A new folder inside an existing one is made.
    CHECK_NOTHROW(prepare_output(dir / "new" / "x.png"));
    CHECK(fs::is_directory(dir / "new"));
    // Two missing levels are an error naming both, and nothing is made.
    const fs::path deep = dir / "missing" / "deeper" / "x.png";
    CHECK_THROWS_WITH(prepare_output(deep), "'" + deep.string() + "': its folder '" +
                                                (dir / "missing" / "deeper").string() + "' does not exist, nor does '" +
                                                (dir / "missing").string() + "'; create it first");
    CHECK_FALSE(fs::exists(dir / "missing"));
    // A file where the folder should be.
    {
        std::FILE* f = std::fopen((dir / "new" / "file").c_str(), "w");
        REQUIRE(f);
        std::fclose(f);
    }
    CHECK_THROWS_WITH(prepare_output(dir / "new" / "file" / "x.png"), Catch::Contains("is not a folder"));
}

TEST_CASE("command line: run_program turns errors into exit statuses 1 and 2", "[app]") {
    CHECK(run_program("prog", [] { return kExitDone; }) == kExitDone);
    CHECK(run_program("prog", []() -> int { throw UsageError("--x: bad"); }) == kExitUsage);
    CHECK(run_program("prog", []() -> int { throw Error("scene.json:1:2: bad"); }) == kExitBadInput);
}
