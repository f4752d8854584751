// A scene's "environment": an envmap found like any file (the studio maps of blender-data by logical name),
// turned by "rotation" to light the side of a sphere it should, the background of every integrator, and the
// errors of a scene that gives it wrongly.
#include <rtlab/core/error.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/scene/scene_loader.hpp>
#include <rtlab/shading/environment_map.hpp>

#include <catch2/catch.hpp>
#include <skip.hpp>

#include <filesystem>
#include <string>

using namespace rtlab;
using Catch::Contains;
namespace fs = std::filesystem;

namespace {

// A black map but for a small bright patch on the horizon at u = 0.25: towards -z when not turned.
fs::path write_patch_map() {
    const fs::path dir = fs::temp_directory_path() / "rtlab_test_environment_scene";
    fs::create_directories(dir);
    Image img(32, 16);
    for (int y = 7; y <= 8; ++y)
        for (int x = 7; x <= 8; ++x) img.at(x, y) = RGB(50.0f);
    write_pfm(img, dir / "patch.pfm");
    return dir;
}

std::string sphere_scene(const std::string& environment, const std::string& integrator) {
    return R"({"version": 1, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 30},
  "render": {"width": 32, "height": 32, "aa": "sobol", "spp": 8, "integrator": ")" +
           integrator + R"(", "environment": )" + environment + R"(},
  "materials": [{"name": "m", "type": "lambert", "albedo": 0.8}],
  "shapes": [{"type": "sphere", "radius": 1, "material": "m"}]})";
}

// The mean luminance of the image's left and right thirds.
std::pair<double, double> left_right(const Image& image) {
    double left = 0.0, right = 0.0;
    const int third = image.width() / 3;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < third; ++x) {
            left += image.at(x, y).luminance();
            right += image.at(image.width() - 1 - x, y).luminance();
        }
    return {left, right};
}

}  // namespace

TEST_CASE("a scene's envmap turned by rotation lights the side of a sphere it should", "[scene]") {
    const fs::path dir = write_patch_map();
    SceneLoadOptions options;
    options.data_dirs = {dir};
    options.use_environment = false;
    // The patch faces -z (behind the sphere, seen from the camera on +z); turned by +90 degrees (counter-clockwise
    // seen from above) it faces -x, the image's left; by -90 degrees +x, the right.
    for (const auto& [degrees, lit_left] : {std::pair{90, true}, std::pair{-90, false}}) {
        for (const char* integrator : {"direct", "path"}) {
            INFO("rotation " << degrees << ", " << integrator);
            const LoadedScene s =
                parse_scene(sphere_scene(R"({"type": "envmap", "filename": "patch.pfm", "rotation": )" +
                                             std::to_string(degrees) + "}",
                                         integrator),
                            "t.json", options);
            REQUIRE(s.job.environment);
            const auto [left, right] = left_right(render_job(s.job).image);
            CHECK((lit_left ? left : right) > 20.0 * (lit_left ? right : left));
        }
    }
    // Not turned, the patch is behind the sphere: its rim alone is lit, on both sides alike.
    const LoadedScene s =
        parse_scene(sphere_scene(R"({"type": "envmap", "filename": "patch.pfm"})", "direct"), "t.json", options);
    const auto [left, right] = left_right(render_job(s.job).image);
    CHECK(left == Approx(right).epsilon(0.3));
}

TEST_CASE("an envmap is the background of the whitted integrator too", "[scene]") {
    const fs::path dir = write_patch_map();
    SceneLoadOptions options;
    options.data_dirs = {dir};
    options.use_environment = false;
    // The camera looks along -z at the patch (u = 0.25 on the horizon), past a small sphere.
    const LoadedScene s = parse_scene(
        R"({"version": 1, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 5},
  "render": {"width": 8, "height": 8, "environment": {"type": "envmap", "filename": "patch.pfm", "intensity": [1, 0.5, 2]}},
  "materials": [{"name": "m", "type": "lambert"}],
  "shapes": [{"type": "sphere", "radius": 0.01, "center": [0, 3, 0], "material": "m"}]})",
        "t.json", options);
    const Image image = render_job(s.job).image;
    CHECK(image.at(4, 4).r == Approx(50.0f).epsilon(1e-3));
    CHECK(image.at(4, 4).g == Approx(25.0f).epsilon(1e-3));
    CHECK(image.at(4, 4).b == Approx(100.0f).epsilon(1e-3));
}

TEST_CASE("a scene's cube map envmap reads six faces or one cross, each face where core's convention puts it",
          "[scene]") {
    // Face f is grey f + 1: the map seen along each axis gives the number of the face there.
    const fs::path dir = fs::temp_directory_path() / "rtlab_test_environment_cube";
    fs::create_directories(dir);
    const char* names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    const int cell[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};  // the horizontal cross
    Image cross(16, 12);
    for (int f = 0; f < 6; ++f) {
        write_pfm(Image(4, 4, RGB(float(f + 1))), dir / (std::string(names[f]) + ".pfm"));
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) cross.at(4 * cell[f][0] + x, 4 * cell[f][1] + y) = RGB(float(f + 1));
    }
    write_pfm(cross, dir / "cross.pfm");
    SceneLoadOptions options;
    options.data_dirs = {dir};
    options.use_environment = false;
    const Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const std::string& env :
         {std::string(R"({"type": "envmap", "px": "px.pfm", "nx": "nx.pfm", "py": "py.pfm", "ny": "ny.pfm",
                          "pz": "pz.pfm", "nz": "nz.pfm"})"),
          std::string(R"({"type": "envmap", "cross": "cross.pfm"})")}) {
        const LoadedScene s = parse_scene(sphere_scene(env, "path"), "t.json", options);
        const auto* map = dynamic_cast<const EnvironmentMap*>(s.job.environment.get());
        REQUIRE(map);
        CHECK(map->is_cube());
        for (int f = 0; f < 6; ++f) CHECK(map->radiance(axes[f]).g == Approx(f + 1.0f));
    }
}

TEST_CASE("a studio map of blender-data is found by its logical name with its credit", "[scene]") {
    SceneLoadOptions options;
    options.use_environment = false;
    options.data_path = DataPath();  // the packages' files only
    if (!options.data_path->find("envmaps/studio.exr")) return test::skip("blender-data is not installed");
    const LoadedScene s =
        parse_scene(sphere_scene(R"({"type": "envmap", "filename": "envmaps/studio.exr", "rotation": 45})", "path"),
                    "t.json", options);
    const auto* map = dynamic_cast<const EnvironmentMap*>(s.job.environment.get());
    REQUIRE(map);
    CHECK(map->options().rotation_degrees == 45.0f);
    CHECK(map->distribution().columns() == 2048);
    REQUIRE(s.assets.size() == 1);
    CHECK_THAT(describe_sources(s.assets),
               Contains("package blender-data") && Contains("Greg Zaal") && Contains("CC0"));
}

TEST_CASE("a scene's environment given wrongly is an error at its keys", "[scene]") {
    const fs::path dir = write_patch_map();
    SceneLoadOptions options;
    options.data_dirs = {dir};
    options.use_environment = false;
    auto error_of = [&](const std::string& environment, const std::string& extra = "") {
        std::string text = sphere_scene(environment, "path");
        if (!extra.empty()) text.insert(text.find("\"environment\""), extra + ", ");
        try {
            parse_scene(text, "t.json", options);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        FAIL("loaded");
        return std::string();
    };
    CHECK_THAT(error_of(R"({"type": "envmap", "filename": "patch.pfm"})", R"("skybox": {"type": "stars"})"),
               Contains("/render/environment: give 'environment' or 'skybox', not both"));
    CHECK_THAT(error_of(R"({"type": "envmap"})"),
               Contains("/render/environment: environment 'envmap': give exactly one of 'filename'"));
    CHECK_THAT(error_of(R"({"type": "envmap", "filename": "patch.pfm", "cross": "patch.pfm"})"),
               Contains("give exactly one of"));
    CHECK_THAT(error_of(R"({"type": "envmap", "px": "patch.pfm"})"),
               Contains("/render/environment: environment 'envmap': parameter 'nx' is missing"));
    CHECK_THAT(error_of(R"({"type": "envmap", "cross": "patch.pfm"})"),
               Contains("/render/environment/cross:") && Contains("is 32x16, not 4N x 3N"));
    CHECK_THAT(error_of(R"({"type": "envmp", "filename": "patch.pfm"})"),
               Contains("unknown environment type 'envmp'; did you mean 'envmap'?"));
    CHECK_THAT(error_of(R"("patch.pfm")"), Contains("/render/environment: expected an environment"));
    CHECK_THAT(error_of(R"({"type": "envmap", "filename": "nothing.exr"})"),
               Contains("/render/environment/filename: file 'nothing.exr' not found"));
}
