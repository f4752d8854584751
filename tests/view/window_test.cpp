// The window itself, under a virtual X server with Mesa's software OpenGL (ctest runs this executable through
// xvfb-run). Driven through standard input; every wait is for a line the viewer prints.
#include "view_process.hpp"

#include <rtlab/core/image.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

struct Rect {
    int x = 0, y = 0, w = 0, h = 0;
};

Rect parse_rect(const std::string& line) {
    Rect r;
    std::istringstream in(line.substr(std::string("image ").size()));
    in >> r.x >> r.y >> r.w >> r.h;
    return r;
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("rtlab_view_window_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read_text(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Writes by rename, as editors save: the viewer must see the moved-to event.
void save_by_rename(const fs::path& file, const std::string& text) {
    std::ofstream(file.string() + ".tmp") << text;
    fs::rename(file.string() + ".tmp", file);
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

/// The 8-bit codes (as code / 255) of the image rectangle of a screenshot.
Image crop(const fs::path& screenshot, const Rect& r) {
    const Image shot = read_image(screenshot, ColorEncoding::linear);
    REQUIRE(shot.width() >= r.x + r.w);
    REQUIRE(shot.height() >= r.y + r.h);
    Image out(r.w, r.h);
    for (int y = 0; y < r.h; ++y)
        for (int x = 0; x < r.w; ++x) out.at(x, y) = shot.at(r.x + x, r.y + y);
    return out;
}

float max_difference(const Image& a, const Image& b) {
    float m = 0.0f;
    for (std::size_t i = 0; i < a.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(a.pixels()[i][c] - b.pixels()[i][c]));
    return m;
}

/// Pixels of the error text's colour (1, 0.45, 0.4), antialiased text included.
int red_pixels(const Image& image) {
    int n = 0;
    for (const RGB& p : image.pixels()) n += p.r > 0.6f && p.g < 0.55f * p.r && p.b < 0.55f * p.r;
    return n;
}

const fs::path kWhitted = fs::path(RTLAB_SOURCE_DIR) / "scenes" / "whitted.json";

std::vector<std::string> view_command(const fs::path& scene, std::vector<std::string> extra) {
    std::vector<std::string> argv{VIEW_EXE, scene.string(), "--width", "160", "--height", "120", "--seed", "5"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
}

}  // namespace

namespace {
/// The viewer's screenshot after 4 passes against rtlab-render's PNG at 4 sobol samples, same seed and operator.
void check_screenshot_matches_render(const std::string& tonemap) {
    const fs::path dir = scratch("shot_" + tonemap);
    test::ViewProcess view(
        view_command(kWhitted, {"--tonemap", tonemap, "--screenshot-after-passes", "4", (dir / "shot.png").string()}));
    const std::string rect_line = view.wait_for("image ");
    REQUIRE_FALSE(rect_line.empty());
    REQUIRE(view.wait_for("saved ") != "");
    REQUIRE(view.wait_exit() == 0);
    const Rect rect = parse_rect(rect_line);
    CHECK(rect.w == 160);
    CHECK(rect.h == 120);

    const std::string render = std::string("'") + RENDER_EXE + "' '" + kWhitted.string() +
                               "' --width 160 --height 120 --seed 5 --aa sobol --spp 4 --tonemap " + tonemap +
                               " --quiet -o '" + (dir / "render.png").string() + "'";
    REQUIRE(std::system(render.c_str()) == 0);
    const Image expected = read_image(dir / "render.png", ColorEncoding::linear);
    const Image shown = crop(dir / "shot.png", rect);
    CHECK(max_difference(shown, expected) <= 1.0f / 255.0f + 1e-6f);
    // Not a blank picture: sky and checkerboard differ.
    CHECK(max_difference(shown, Image(160, 120, shown.at(0, 0))) > 0.3f);
    fs::remove_all(dir);
}
}  // namespace

TEST_CASE("the window's screenshot shows rtlab-render's tone-mapped image 1:1", "[gui]") {
    check_screenshot_matches_render("none");
}

TEST_CASE("the window's Reinhard shader matches rtlab-render's reinhard operator", "[gui]") {
    check_screenshot_matches_render("reinhard");
}

TEST_CASE("the window re-renders an edited scene and keeps the image over a broken edit", "[gui]") {
    const fs::path dir = scratch("reload");
    const fs::path scene = dir / "scene.json";
    const std::string original = read_text(kWhitted);
    std::ofstream(scene) << original;
    test::ViewProcess view(view_command(scene, {"--stdin", "--spp", "2"}));
    const Rect rect = parse_rect(view.wait_for("image "));
    REQUIRE(view.wait_for("pass 2") != "");
    view.send("screenshot " + (dir / "a.png").string());
    REQUIRE(view.wait_for("saved ") != "");

    // A broken edit, written in place: the loader's message (file:line:col) on the output and in the window.
    std::ofstream(scene) << replace(original, "\"max_depth\": 8", "\"max_depth\": 8,,");
    const std::string error = view.wait_for("error");
    CHECK_THAT(error, Catch::Contains("scene.json:"));
    view.send("screenshot " + (dir / "b.png").string());
    REQUIRE(view.wait_for("saved ") != "");
    CHECK(max_difference(crop(dir / "a.png", rect), crop(dir / "b.png", rect)) == 0.0f);
    // The panel shows the error text, in red: no other text or control there is red.
    const Rect panel{0, 0, rect.x, read_image(dir / "a.png").height()};
    CHECK(red_pixels(crop(dir / "a.png", panel)) == 0);
    CHECK(red_pixels(crop(dir / "b.png", panel)) > 200);

    // A good edit saved by rename: a new sky.
    save_by_rename(scene, replace(original, "\"background\": [0.25, 0.5, 0.95]", "\"background\": [0.9, 0.3, 0.1]"));
    REQUIRE(view.wait_for("reloaded") != "");
    REQUIRE(view.wait_for("pass 2") != "");
    view.send("screenshot " + (dir / "c.png").string());
    REQUIRE(view.wait_for("saved ") != "");
    const Image sky_before = crop(dir / "a.png", Rect{rect.x, rect.y, rect.w, 4});
    const Image sky_after = crop(dir / "c.png", Rect{rect.x, rect.y, rect.w, 4});
    CHECK(sky_after.at(0, 0).r > sky_before.at(0, 0).r + 0.3f);
    view.send("quit");
    CHECK(view.wait_exit() == 0);
    fs::remove_all(dir);
}

TEST_CASE("camera input changes the image and reset brings the file's image back", "[gui]") {
    const fs::path dir = scratch("camera");
    test::ViewProcess view(view_command(kWhitted, {"--stdin", "--spp", "1"}));
    const Rect rect = parse_rect(view.wait_for("image "));
    REQUIRE(view.wait_for("pass 1") != "");
    view.send("screenshot " + (dir / "a.png").string());
    REQUIRE(view.wait_for("saved ") != "");
    view.send("orbit 25 10");
    view.send("print-camera");
    const std::string snippet = view.wait_for("\"camera\"");
    CHECK_THAT(snippet, Catch::Contains("\"look_at\": [0, 0.9, -2.5]"));
    CHECK_THAT(snippet, !Catch::Contains("\"position\": [0, 2, 4]"));
    REQUIRE(view.wait_for("pass 1") != "");
    view.send("screenshot " + (dir / "b.png").string());
    REQUIRE(view.wait_for("saved ") != "");
    CHECK(max_difference(crop(dir / "a.png", rect), crop(dir / "b.png", rect)) > 0.3f);
    view.send("reset");
    REQUIRE(view.wait_for("pass 1") != "");
    view.send("screenshot " + (dir / "c.png").string());
    REQUIRE(view.wait_for("saved ") != "");
    CHECK(max_difference(crop(dir / "a.png", rect), crop(dir / "c.png", rect)) == 0.0f);
    view.send("quit");
    CHECK(view.wait_exit() == 0);
    fs::remove_all(dir);
}

TEST_CASE("without a display the viewer says so in one line and exits 1", "[gui]") {
    const fs::path dir = scratch("nodisplay");
    const std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY '" + std::string(VIEW_EXE) + "' '" +
                                kWhitted.string() + "' 2> '" + (dir / "err.txt").string() + "'";
    const int raw = std::system(command.c_str());
    REQUIRE(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == 1);
    const std::string err = read_text(dir / "err.txt");
    CHECK(err.rfind("rtlab-view: no display", 0) == 0);
    CHECK(std::count(err.begin(), err.end(), '\n') == 1);
    fs::remove_all(dir);
}
