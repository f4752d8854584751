// rtlab-render --record-rays: the ray files of a fitted, transformed mesh are in the mesh file's own coordinates
// (the structure built from the file answers them as the render's mesh did), the image is the same bytes, and bad
// command lines name the option.
#include "app_run.hpp"

#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/ray_io.hpp>
#include <rtlab/geometry/mesh_io.hpp>
#include <scratch_files.hpp>
#include <test_meshes.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace rtlab;
using test::run_app;
namespace fs = std::filesystem;

namespace {

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

std::vector<unsigned char> bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The number after `label` on the line of `out` that holds `line`.
double printed(const std::string& out, const std::string& line, const std::string& label) {
    std::size_t start = out.find(line);
    REQUIRE(start != std::string::npos);
    start = out.rfind('\n', start);
    start = start == std::string::npos ? 0 : start;
    const std::size_t at = out.find(label, start);
    REQUIRE(at != std::string::npos);
    return std::stod(out.substr(at + label.size()));
}

/// A ball off the origin as an OBJ file and a path-traced scene that fits it, turns it and moves it (the bunny's
/// placement in scenes/cornell_box_bunny.json), over a floor under a point light and a lamp.
fs::path write_scene(const fs::path& dir) {
    const TriangleMesh ball = test::icosphere(2, 1.0f, Point3(3.0f, 1.0f, -2.0f));
    std::ofstream obj(dir / "ball.obj");
    for (const Point3& p : ball.positions) obj << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : ball.triangles) obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    const fs::path scene = dir / "ball.json";
    std::ofstream(scene) << R"({
  "version": 1,
  "camera": {"position": [0, 1.2, 3], "look_at": [0, 0.4, 0], "fov": 40},
  "render": {"width": 16, "height": 16, "aa": "sobol", "spp": 4, "integrator": "path", "max_depth": 4,
             "convention": "physical", "background": 0.2, "tonemap": "none"},
  "materials": [
    {"name": "clay", "type": "lambert", "albedo": [0.8, 0.6, 0.4]},
    {"name": "floor", "type": "lambert", "albedo": 0.5},
    {"name": "lamp", "type": "lambert", "albedo": 0, "emission": 5}
  ],
  "lights": [{"type": "point", "position": [-2, 4, 2], "intensity": 20}],
  "shapes": [
    {"name": "ball", "type": "mesh", "filename": "ball.obj", "fit": 0.8, "material": "clay",
     "transform": {"rotate": [0, 200, 0], "translate": [0.1, 0, -0.2]}},
    {"name": "floor", "type": "quad", "corner": [-3, 0, 3], "edge_u": [6, 0, 0], "edge_v": [0, 0, -6],
     "material": "floor"},
    {"name": "lamp", "type": "sphere", "center": [0.8, 1.6, 0.5], "radius": 0.2, "material": "lamp"}
  ]
})";
    return scene;
}

}  // namespace

TEST_CASE("rtlab-render --record-rays writes the rays of a fitted mesh in its file's coordinates", "[apps]") {
    const fs::path dir = test::scratch_dir("apps_record_rays");
    const fs::path scene = write_scene(dir);
    const auto plain = run_app(RENDER_EXE, q(scene) + " -o " + q(dir / "plain.pfm"), dir);
    INFO(plain.out << plain.err);
    REQUIRE(plain.status == 0);
    const fs::path prefix = dir / "rays" / "ball";  // the folder is made, as -o makes its own
    const auto run = run_app(
        RENDER_EXE, q(scene) + " -o " + q(dir / "recorded.pfm") + " --record-rays ball --record-out " + q(prefix), dir);
    INFO(run.out << run.err);
    REQUIRE(run.status == 0);
    CHECK(bytes_of(dir / "plain.pfm") == bytes_of(dir / "recorded.pfm"));

    const std::vector<Ray> closest = read_ray_file(prefix.string() + ".closest.rays");
    const std::vector<Ray> shadow = read_ray_file(prefix.string() + ".shadow.rays");
    CHECK(closest.size() == static_cast<std::size_t>(printed(run.out, "closest-hit queries", "; wrote ")));
    CHECK(shadow.size() == static_cast<std::size_t>(printed(run.out, "shadow queries", "; wrote ")));
    CHECK(closest.size() > 100);
    CHECK(shadow.size() > 100);

    // The file's mesh and a structure built from it, as rtlab-accel --mesh builds it: every ray overlaps the file's
    // box, and the share that hits (blocked) is the one the render printed.
    const TriangleMesh mesh = load_mesh(dir / "ball.obj");
    const auto accel = make_accelerator("kd-sah", mesh);
    std::size_t outside = 0, hits = 0, blocked = 0;
    for (const Ray& r : closest) {
        outside += !mesh.bounds().intersect(r);
        MeshHit h;
        hits += accel->intersect(r, h);
    }
    for (const Ray& r : shadow) {
        outside += !mesh.bounds().intersect(r);
        blocked += accel->occluded(r);
    }
    CHECK(outside == 0);
    const double hit_share = 100.0 * static_cast<double>(hits) / static_cast<double>(closest.size());
    const double blocked_share = 100.0 * static_cast<double>(blocked) / static_cast<double>(shadow.size());
    CHECK(hits > 20);
    CHECK(blocked > 20);
    CHECK(printed(run.out, "closest-hit queries", "(") == Approx(hit_share).margin(0.051));
    CHECK(printed(run.out, "shadow queries", "(") == Approx(blocked_share).margin(0.051));
}

TEST_CASE("rtlab-render --record-rays with a bad name or path or without its partner names the option", "[apps]") {
    const fs::path dir = test::scratch_dir("apps_record_rays_errors");
    const fs::path scene = write_scene(dir);
    const std::string render = q(scene) + " -o " + q(dir / "out.pfm") + " ";
    const auto unknown = run_app(RENDER_EXE, render + "--record-rays bal --record-out " + q(dir / "x"), dir);
    CHECK(unknown.status == 1);
    CHECK(unknown.err.find("--record-rays bal: no object named 'bal'; did you mean 'ball'?") != std::string::npos);
    const auto lamp = run_app(RENDER_EXE, render + "--record-rays lamp --record-out " + q(dir / "x"), dir);
    CHECK(lamp.status == 1);
    CHECK(lamp.err.find("--record-rays lamp: object 'lamp' emits light") != std::string::npos);
    const auto nowhere =
        run_app(RENDER_EXE, render + "--record-rays ball --record-out " + q(dir / "no" / "such" / "x"), dir);
    CHECK(nowhere.status == 1);
    CHECK(nowhere.err.find("--record-out " + (dir / "no" / "such" / "x").string() + ": ") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "out.pfm"));  // nothing rendered
    const auto alone = run_app(RENDER_EXE, render + "--record-out " + q(dir / "x"), dir);
    CHECK(alone.status == 2);
    CHECK(alone.err.find("--record-out goes with --record-rays NAME") != std::string::npos);
    const auto no_out = run_app(RENDER_EXE, render + "--record-rays ball", dir);
    CHECK(no_out.status == 2);
    CHECK(no_out.err.find("give --record-out PREFIX") != std::string::npos);
    const auto threads = run_app(RENDER_EXE, render + "--record-rays ball --record-out x --threads 2", dir);
    CHECK(threads.status == 2);
    CHECK(threads.err.find("--record-rays renders on one thread") != std::string::npos);
}
