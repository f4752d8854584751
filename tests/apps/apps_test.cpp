// rtlab-whitted and rtlab-bunny, and the flags every course app shares.
#include "app_run.hpp"

#include <rtlab/app/course_app.hpp>
#include <rtlab/geometry/mesh_io.hpp>
#include <shared_data.hpp>
#include <skip.hpp>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>

#include "../../apps/bunny/scene.hpp"
#include "../../apps/whitted/scene.hpp"

using namespace rtlab;
using test::run_app;

namespace {

bool is_red(const RGB& c) { return c.r > 0.3f && c.g < 0.12f && c.b < 0.12f; }
bool is_yellow(const RGB& c) { return c.r > 0.4f && c.g > 0.35f && c.b < 0.15f; }
bool is_sky_blue(const RGB& c) { return c.b > 0.7f && c.b > c.r + 0.4f && c.b > c.g + 0.2f; }

}  // namespace

TEST_CASE("whitted: red and yellow checkerboard below, blue sky above, the spheres in between", "[apps]") {
    RenderJob job = whitted::make_whitted_job(64, 48);
    job.settings.threads = 2;
    const Image image = render_job(job).image;
    int sky_top = 0, red = 0, yellow = 0;
    for (int x = 0; x < 64; ++x) sky_top += is_sky_blue(image.at(x, 0)) ? 1 : 0;
    for (int y = 24; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            red += is_red(image.at(x, y)) ? 1 : 0;
            yellow += is_yellow(image.at(x, y)) ? 1 : 0;
        }
    CHECK(sky_top == 64);      // the whole top row is sky
    CHECK(red > 64 * 24 / 6);  // each colour covers a good part of the lower half
    CHECK(yellow > 64 * 24 / 6);
    // Above the horizon, the spheres stand against the sky: pixels there that differ from the background are
    // the mirror sphere (right of centre) and the glass shell (left of centre).
    auto spheres = [&](int x0, int x1) {
        int n = 0;
        for (int y = 12; y < 21; ++y)
            for (int x = x0; x < x1; ++x) {
                const RGB d = image.at(x, y) - job.whitted.background;
                n += std::max({std::abs(d.r), std::abs(d.g), std::abs(d.b)}) > 0.02f ? 1 : 0;
            }
        return n;
    };
    CHECK(spheres(36, 50) > 20);
    CHECK(spheres(8, 26) > 20);
}

TEST_CASE("whitted: the glass shell lets shadow rays through, the mirror sphere does not", "[apps]") {
    const RenderJob job = whitted::make_whitted_job(64, 48);
    const auto& objects = job.scene->objects();
    REQUIRE(objects.size() == 4);
    CHECK_FALSE(objects[1].material->transmits_shadows());  // the mirror sphere
    CHECK(objects[2].material->transmits_shadows());        // the glass shell, outside and inside
    CHECK(objects[3].material->transmits_shadows());
    CHECK(objects[2].material->ior_inside() == 1.5f);
    CHECK(objects[3].material->ior_inside() == 1.0f);  // air inside the shell
    CHECK(objects[3].material->ior_outside() == 1.5f);
}

TEST_CASE("course apps: data files are looked up in --data-dir, RTLAB_DATA_PATH, then beside the checkout", "[apps]") {
    const auto dir = test::scratch_dir("apps_data_path");
    const auto a = dir / "a", b = dir / "b";
    std::filesystem::create_directories(a / "textures");
    std::filesystem::create_directories(b / "textures");
    { std::ofstream(a / "textures" / "only_a.txt") << "a"; }
    { std::ofstream(b / "textures" / "both.txt") << "b"; }
    { std::ofstream(a / "textures" / "both.txt") << "a"; }
    ::setenv("RTLAB_DATA_PATH", b.c_str(), 1);
    ::unsetenv("RTLAB_SHARED_DIR");
    app::CourseOptions o;
    o.data_dirs = {a};
    // As if the executable were build/release/bin/x of this checkout.
    const auto exe = std::filesystem::path(RTLAB_SOURCE_DIR) / "build" / "release" / "bin" / "x";
    const DataPath path = app::course_data_path(o, exe, "test");
    REQUIRE(path.roots().size() >= 2);
    CHECK(path.roots()[0].folder == a);
    CHECK(path.roots()[1].folder == b);
    CHECK(path.find("textures/both.txt")->path == a / "textures" / "both.txt");  // --data-dir first
    CHECK(path.find("textures/both.txt")->source == "--data-dir " + a.string());
    const auto beside = std::filesystem::path(RTLAB_SOURCE_DIR).parent_path() / "shared";
    if (std::filesystem::is_directory(beside) && !test::shared_disabled()) {
        REQUIRE(path.roots().size() == 3);
        CHECK(path.roots()[2].folder == std::filesystem::weakly_canonical(beside));
    } else {
        CHECK(path.roots().size() == 2);
    }
    ::unsetenv("RTLAB_DATA_PATH");
}

TEST_CASE("course apps: a --data-dir folder that does not exist is a warning naming the program", "[apps]") {
    const auto dir = test::scratch_dir("apps_missing_data_dir");
    const std::string out = " -o '" + (dir / "out.pfm").string() + "'";
    const auto solar =
        run_app(SOLAR_EXE, "--procedural --width 8 --height 6 --quiet --data-dir /nonexistent" + out, dir);
    CHECK(solar.status == 0);
    CHECK(solar.err == "rtlab-solar-system: warning: --data-dir '/nonexistent' does not exist\n");
    const auto whitted = run_app(
        WHITTED_EXE, "--width 8 --height 6 --quiet --data-dir /nonexistent --data-dir /nonexistent2" + out, dir);
    CHECK(whitted.status == 0);
    CHECK(whitted.err ==
          "rtlab-whitted: warning: --data-dir '/nonexistent' does not exist\n"
          "rtlab-whitted: warning: --data-dir '/nonexistent2' does not exist\n");
    // RTLAB_DATA_PATH's folders too, named by the variable.
    const auto bunny = run_app(BUNNY_EXE, "--width 8 --height 6 --quiet --mesh /nonexistent.obj" + out, dir,
                               "RTLAB_DATA_PATH=/nonexistent3");
    CHECK(bunny.status == 1);
    CHECK_THAT(bunny.err, Catch::Matchers::StartsWith(
                              "rtlab-bunny: warning: RTLAB_DATA_PATH '/nonexistent3' does not exist\nrtlab-bunny: "));
}

TEST_CASE("course apps: a fresh machine without ../shared renders the bunny and the planets from the packages",
          "[apps]") {
    // The data path limited to what a user has: no ../shared (RTLAB_NO_SHARED=1), no RTLAB_DATA_PATH, only
    // the Debian data packages. Each app must say where its data came from and use the real assets.
    if (!test::packages_installed())
        return test::skip("glmark2-data and openuniverse-common are not installed (scripts/setup.sh)");
    const auto dir = test::scratch_dir("apps_fresh_machine");
    const std::string user = "RTLAB_NO_SHARED=1 RTLAB_DATA_PATH= RTLAB_SHARED_DIR=";
    const std::string size = " --width 64 --height 48 --threads 2 -o '";
    const auto bunny = run_app(BUNNY_EXE, "--aa none" + size + (dir / "bunny.pfm").string() + "'", dir, user);
    REQUIRE(bunny.status == 0);
    CHECK(bunny.err.empty());
    CHECK_THAT(bunny.out, Catch::Matchers::Contains("data: models/stanford-bunny.obj from package glmark2-data; "
                                                    "credits: Stanford bunny: The Stanford 3D Scanning Repository"));
    CHECK_THAT(bunny.out, Catch::Matchers::Contains("/usr/share/glmark2/models/bunny.obj: 69666 triangles"));
    const auto solar = run_app(SOLAR_EXE, "--aa none" + size + (dir / "solar.pfm").string() + "'", dir, user);
    REQUIRE(solar.status == 0);
    CHECK(solar.err.empty());
    // Every planet and the rings from the package; only what no package has stays procedural.
    CHECK_THAT(solar.out, Catch::Matchers::Contains(
                              "data: textures/sun.jpg, textures/skybox/ procedural; textures/mercury.jpg, "
                              "textures/venus.jpg, textures/earth.jpg, textures/mars.jpg, textures/jupiter.jpg, "
                              "textures/saturn.jpg, textures/uranus.jpg, textures/neptune.jpg, "
                              "textures/saturn_ring.png from package openuniverse-common; credits: OpenUniverse"));
    // The package maps, not the procedural ones: the picture differs from --procedural's.
    const auto procedural =
        run_app(SOLAR_EXE, "--procedural --aa none" + size + (dir / "procedural.pfm").string() + "'", dir, user);
    REQUIRE(procedural.status == 0);
    CHECK_FALSE(test::same_pixels(read_pfm(dir / "solar.pfm"), read_pfm(dir / "procedural.pfm")));
    const auto whitted = run_app(WHITTED_EXE, size.substr(1) + (dir / "whitted.pfm").string() + "'", dir, user);
    CHECK(whitted.status == 0);
    CHECK(whitted.err.empty());
}

TEST_CASE("whitted: adaptive anti-aliasing by default, flags override it", "[apps]") {
    RenderJob job = whitted::make_whitted_job(64, 48);
    CHECK(job.settings.pattern == PixelPattern::adaptive);
    CHECK(job.whitted.convention == Convention::classic);
    app::CourseOptions o;
    // --spp alone never switches the pattern: adaptive takes no sample count.
    o.spp = 9;
    CHECK_THROWS_AS(app::apply_course_options(o, job), app::UsageError);
    o.aa = "jittered";
    app::apply_course_options(o, job);
    CHECK(job.settings.pattern == PixelPattern::jittered);
    CHECK(job.settings.spp == 9);
    o.aa = "none";
    o.spp.reset();
    o.seed = 42;
    o.max_depth = 2;
    app::apply_course_options(o, job);
    CHECK(job.settings.pattern == PixelPattern::none);
    CHECK(job.settings.seed == 42);
    CHECK(job.whitted.max_depth == 2);
}

TEST_CASE("rtlab-whitted writes the image of the scene function, byte for byte", "[apps]") {
    const auto dir = test::scratch_dir("apps_whitted");
    const auto out = dir / "whitted.pfm";
    std::filesystem::remove(out);
    const auto run = run_app(WHITTED_EXE, "--width 64 --height 48 --threads 2 --quiet -o '" + out.string() + "'", dir);
    REQUIRE(run.status == 0);
    const Image written = read_pfm(out);
    RenderJob job = whitted::make_whitted_job(64, 48);
    CHECK(test::same_pixels(written, render_job(job).image));
}

TEST_CASE("course apps: bad flags exit 2 and bad input 1 with a message", "[apps]") {
    const auto dir = test::scratch_dir("apps_flags");
    struct Case {
        const char* exe;
        const char* args;
        int status;
        const char* message;
    };
    const Case cases[] = {
        {WHITTED_EXE, "--bogus", 2, "rtlab-whitted: unknown option '--bogus'"},
        {WHITTED_EXE, "--width 0", 2, "rtlab-whitted: --width: must be at least 1, not 0"},
        {WHITTED_EXE, "--aa sideways", 2, "rtlab-whitted: --aa: 'sideways' is not one of"},
        {WHITTED_EXE, "--spp many", 2, "rtlab-whitted: --spp: expected a whole number, not 'many'"},
        {WHITTED_EXE, "-o whitted.tiff", 2, "rtlab-whitted: -o: 'whitted.tiff': unknown image format"},
        {BUNNY_EXE, "--material velvet", 2, "rtlab-bunny: --material: 'velvet' is not one of"},
        {BUNNY_EXE, "--mesh no-such-mesh.obj", 1, "rtlab-bunny: 'no-such-mesh.obj'"},
        {SOLAR_EXE, "--frame-range 1:2", 2, "rtlab-solar-system: --frame-range needs --frames"},
        {SOLAR_EXE, "--frames 4 --frame-range 3:2", 2, "3:2"},
        {SOLAR_EXE, "--frames 4 --frame-range 0:5", 2, "0:5"},
        {SOLAR_EXE, "--frames 4 --frame-range two", 2, "two"},
        {SOLAR_EXE, "--frames 0", 2, "rtlab-solar-system: --frames: must be in [1, 100000], not 0"},
    };
    for (const Case& c : cases) {
        INFO(c.exe << " " << c.args);
        // The case's own values last: a flag given twice takes the last value.
        const std::string args = "--quiet --width 8 --height 6 " + std::string(c.args);
        const auto run = run_app(c.exe, args, dir);
        CHECK(run.status == c.status);
        CHECK_THAT(run.err, Catch::Matchers::Contains(c.message));
    }
    // --help is not an error.
    CHECK(run_app(WHITTED_EXE, "--help", dir).status == 0);
}

TEST_CASE("bunny: any mesh stands in the middle of the picture on the floor", "[apps]") {
    // A small closed mesh (an octahedron) stands in for the bunny, so the test needs no data files.
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    mesh->triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const auto smooth = std::make_shared<const TriangleMesh>(with_smooth_normals(*mesh));
    REQUIRE(smooth->has_normals());
    CHECK(glm::length(smooth->normals[0] - Normal3(1, 0, 0)) < 1e-6f);  // the corner's faces average to the axis
    RenderJob job = bunny::make_bunny_job(smooth, "diffuse", 64, 48);
    const Image image = render_job(job).image;
    // The diffuse material is warm (r > b); the sky is blue (b > r) and the floor grey (r = b).
    auto warm = [&](int x, int y) { return image.at(x, y).r > image.at(x, y).b + 0.03f; };
    CHECK(warm(32, 24));
    int corners = 0;
    for (int y : {1, 46})
        for (int x : {1, 62}) corners += warm(x, y) ? 1 : 0;
    CHECK(corners == 0);
    CHECK_THROWS_WITH(bunny::make_bunny_job(smooth, "velvet", 64, 48),
                      Catch::Contains("diffuse, phong, mirror, glass"));
}

TEST_CASE("rtlab-bunny reports the faces a mesh loader dropped and renders the rest", "[apps]") {
    const auto dir = test::scratch_dir("apps_bunny_warning");
    // An octahedron's upper half as a PLY, with a two-corner face between its triangles, on one thread.
    const auto mesh = dir / "short-face.ply";
    std::ofstream(mesh) << "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 5\nproperty list uchar int vertex_indices\nend_header\n"
                           "1 0 0\n-1 0 0\n0 0 1\n0 0 -1\n0 1 0\n"
                           "3 0 4 2\n2 2 4\n3 2 4 1\n3 1 4 3\n3 3 4 0\n";
    const auto out = dir / "short-face.pfm";
    std::filesystem::remove(out);
    const auto run = run_app(
        BUNNY_EXE,
        "--width 32 --height 24 --aa none --quiet --threads 1 --mesh '" + mesh.string() + "' -o '" + out.string() + "'",
        dir);
    REQUIRE(run.status == 0);
    CHECK_THAT(run.err, Catch::Matchers::Contains("rtlab-bunny: warning: " + mesh.string() +
                                                  ": 1 face with fewer than 3 corners dropped (line 16: element "
                                                  "'face' #1)"));
    CHECK(std::filesystem::is_regular_file(out));

    // Left with no triangle, the mesh is an error naming the file, and nothing is written.
    const auto segment = dir / "segment.ply";
    std::ofstream(segment) << "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                              "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n2 0 1\n";
    const auto none = dir / "segment.pfm";
    std::filesystem::remove(none);
    const auto bad = run_app(BUNNY_EXE, "--quiet --mesh '" + segment.string() + "' -o '" + none.string() + "'", dir);
    CHECK(bad.status == 1);
    CHECK_THAT(bad.err, Catch::Matchers::Contains("segment.ply") && Catch::Matchers::Contains("no triangles"));
    CHECK_FALSE(std::filesystem::exists(none));
}

namespace {

// Renders rtlab-bunny in each material with its mesh from one data source (the --data-dir root alone).
void check_bunny_materials(test::DataSource source) {
    const auto root = test::data_root(source);
    if (!root)
        return test::skip(std::string("no ") + test::source_name(source) + " data for models/stanford-bunny.obj");
    const auto dir = test::scratch_dir(std::string("apps_bunny_") + test::source_name(source));
    for (const char* material : {"diffuse", "phong", "mirror", "glass"}) {
        INFO(material);
        const auto out = dir / (std::string("bunny-") + material + ".pfm");
        std::filesystem::remove(out);
        const auto run = run_app(BUNNY_EXE,
                                 std::string("--width 64 --height 48 --aa none --quiet --material ") + material +
                                     " --data-dir '" + root->string() + "' -o '" + out.string() + "'",
                                 dir, "RTLAB_NO_SHARED=1 RTLAB_DATA_PATH=");
        REQUIRE(run.status == 0);
        const Image image = read_pfm(out);
        // The silhouette is in the middle: the centre differs from what the corners (sky, floor) show there
        // without the bunny, and the picture is not blank.
        const RGB centre = test::mean(image, 28, 20, 36, 28);
        const RGB sky = test::mean(image, 0, 0, 64, 4);
        CHECK(sky.b > sky.r);
        CHECK(glm::length(Vec3(centre.r - sky.r, centre.g - sky.g, centre.b - sky.b)) > 0.05f);
        if (std::string(material) == "diffuse") CHECK(centre.r > centre.b + 0.03f);
    }
}

}  // namespace

TEST_CASE("rtlab-bunny renders the Stanford bunny in each material from ../shared", "[apps]") {
    check_bunny_materials(test::DataSource::shared);
}

TEST_CASE("rtlab-bunny renders the Stanford bunny in each material from glmark2-data", "[apps]") {
    check_bunny_materials(test::DataSource::packages);
}
