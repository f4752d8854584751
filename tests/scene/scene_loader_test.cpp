#include <rtlab/core/error.hpp>
#include <rtlab/scene/scene_loader.hpp>
#include <rtlab/textures/mip_map.hpp>

#include <catch2/catch.hpp>
#include <scratch_files.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using namespace rtlab;

namespace {

// The message of the one Error a scene gives.
std::string load_error(const std::string& text, const SceneLoadOptions& options = {}) {
    try {
        parse_scene(text, "t.json", options);
    } catch (const Error& e) {
        return e.what();
    }
    FAIL("the scene loaded");
    return {};
}

int line_count(const std::string& s) { return 1 + static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

const char* const kGood = R"({
  "version": 1,
  // comments are allowed
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40},
  "render": {"width": 40, "height": 30, "aa": {"mode": "adaptive", "max_depth": 2}, "seed": 7, "tonemap": "reinhard"},
  "textures": [{"name": "c", "type": "checker", "color1": [1, 0, 0]}],
  "materials": [{"name": "m", "type": "lambert", "albedo": "c"}, {"name": "n", "type": "phong", "kd": {"type": "solid", "color": 0.3}}],
  "lights": [{"type": "point", "position": [0, 5, 5]}],
  "shapes": [
    {"name": "ball", "type": "sphere", "radius": 1, "material": "m", "visible": false},
    {"type": "instance", "shape": "ball", "material": "m", "transform": {"translate": [-1, 0, 0]}},
    {"type": "instance", "shape": "ball", "material": "n", "transform": [{"scale": 0.5}, {"translate": [1, 0, 0]}]}
  ]
})";

}  // namespace

TEST_CASE("a good scene gives its camera, settings, lights and objects", "[scene_loader]") {
    const LoadedScene s = parse_scene(kGood, "t.json");
    REQUIRE(s.job.camera);
    CHECK(s.job.camera->width() == 40);
    CHECK(s.job.camera->height() == 30);
    CHECK(s.job.settings.pattern == PixelPattern::adaptive);
    CHECK(s.job.settings.adaptive.max_depth == 2);
    CHECK(s.job.settings.seed == 7);
    CHECK(s.tone_name == "reinhard");
    CHECK(s.tone != nullptr);
    CHECK(s.job.lights.size() == 1);
    // The invisible original is not drawn; its two instances are, at their own places and sizes.
    REQUIRE(s.job.scene->object_count() == 2);
    const AABB b = s.job.scene->bounds();
    CHECK(b.lo.x == Approx(-2.0f));
    CHECK(b.hi.x == Approx(1.5f));
}

TEST_CASE("command-line overrides replace the file's values and are checked", "[scene_loader]") {
    SceneLoadOptions o;
    o.overrides.width = 80;          // alone: the height keeps the 4:3 aspect ratio
    o.overrides.aa.emplace("grid");  // emplace: GCC 12 at -O1 + ASan warns on assigning a char* to an empty optional
    o.overrides.spp = 9;
    o.overrides.seed = 3;
    o.overrides.tonemap.emplace("none");
    const LoadedScene s = parse_scene(kGood, "t.json", o);
    CHECK(s.job.camera->width() == 80);
    CHECK(s.job.camera->height() == 60);
    CHECK(s.job.settings.pattern == PixelPattern::grid);
    CHECK(s.job.settings.spp == 9);
    CHECK(s.job.settings.seed == 3);
    CHECK(s.tone == nullptr);
    o.overrides.width = 100000;
    CHECK_THAT(load_error(kGood, o), Catch::Contains("--width/--height"));
}

TEST_CASE("scene errors carry file line column and pointer and come all together", "[scene_loader]") {
    const std::string text =
        "{\n"
        "  \"version\": 1,\n"
        "  \"camera\": {\"fov\": \"wide\"},\n"
        "  \"materials\": [{\"name\": \"m\", \"type\": \"phong\", \"ks\": -1, \"kd\": \"nothing\"},\n"
        "                {\"name\": \"m\", \"type\": \"plastic\"}],\n"
        "  \"shapes\": [{\"type\": \"sphere\", \"material\": \"q\", \"colour\": 1}],\n"
        "  \"extra\": true, \"version\": 1\n"
        "}\n";
    const std::string e = load_error(text);
    INFO(e);
    CHECK_THAT(e, Catch::Contains("t.json:3:14: /camera/fov: expected a number, not the string \"wide\""));
    CHECK_THAT(e, Catch::Contains("t.json:4:"));
    CHECK_THAT(e, Catch::Contains("/materials/0/kd: no texture named 'nothing'"));
    CHECK_THAT(e, Catch::Contains("t.json:5:18: /materials/1/name: duplicate material name 'm'"));
    CHECK_THAT(e, Catch::Contains("/materials/1/type: unknown material type 'plastic'"));
    CHECK_THAT(e, Catch::Contains("/shapes/0/material: no material named 'q'"));
    CHECK_THAT(e, Catch::Contains("t.json:7:3: (top level)/extra: unknown key 'extra'") ||
                      Catch::Contains("t.json:7:3: /extra: unknown key 'extra'"));
    CHECK_THAT(e, Catch::Contains("t.json:7:18: (top level): duplicate key 'version' (first at 2:3)"));
    CHECK(line_count(e) >= 7);
}

TEST_CASE("the photon mapping settings are read and checked", "[scene_loader]") {
    const std::string head = R"({"version": 1, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "materials": [{"name": "m", "type": "lambert"}], "shapes": [{"type": "sphere", "material": "m"}],
      "render": {"integrator": "sppm", "aa": "sobol", )";
    const LoadedScene s = parse_scene(
        head + R"("photons": {"count": 5000, "nearest": 30, "max_radius": 0.2, "gather": 3, "filter": "cone",
                              "radius": 0.05, "alpha": 0.5}}})",
        "t.json");
    CHECK(s.job.integrator == IntegratorKind::sppm);
    CHECK(s.job.photons.photons == 5000u);
    CHECK(s.job.photons.nearest == 30);
    CHECK(s.job.photons.max_radius == Approx(0.2f));
    CHECK(s.job.photons.gather == 3);
    CHECK(s.job.photons.filter == PhotonFilter::cone);
    CHECK(s.job.photons.radius == Approx(0.05f));
    CHECK(s.job.photons.alpha == Approx(0.5f));
    const std::string e =
        load_error(head + R"("photons": {"count": 0, "filter": "gauss", "alpha": 1, "nearest": 10, "radious": 1}}})");
    INFO(e);
    CHECK_THAT(e, Catch::Contains("/render/photons/count: "));
    CHECK_THAT(e, Catch::Contains("/render/photons/filter: unknown filter 'gauss'"));
    CHECK_THAT(e, Catch::Contains("/render/photons/alpha: must be in (0, 1)"));
    CHECK_THAT(e, Catch::Contains("/render/photons/radious: unknown key 'radious'"));
    SceneLoadOptions o;
    o.overrides.integrator.emplace("photon");
    CHECK(parse_scene(head + "\"spp\": 2}}", "t.json", o).job.integrator == IntegratorKind::photon);
    o.overrides.integrator.emplace("photons");
    CHECK_THAT(load_error(head + "\"spp\": 2}}", o), Catch::Contains("did you mean 'photon'"));
}

TEST_CASE("syntax errors give the line and column of the error", "[scene_loader]") {
    CHECK_THAT(load_error("{\n  \"version\": 1,\n  \"camera\": {]\n}"), Catch::StartsWith("t.json:3:"));
    CHECK_THAT(load_error("   \n"), Catch::Contains("the file is empty"));
    CHECK_THAT(load_error("[1, 2]"), Catch::Contains("expected a scene (a JSON object), not a list of 2 values"));
}

TEST_CASE("plugins are names given to the loader before types are looked up", "[scene_loader]") {
    const std::string scene = R"({"version": 1, "plugins": ["extra"], "camera": {},
        "materials": [{"name": "m", "type": "plugin-matte"}],
        "shapes": [{"type": "sphere", "material": "m"}]})";
    CHECK_THAT(load_error(scene), Catch::Contains("/plugins/0: the scene needs plugin 'extra', but this program "
                                                  "loads no plugins"));
    SceneRegistries registries = SceneRegistries::builtins();
    std::vector<std::string> loaded;
    SceneLoadOptions o;
    o.registries = &registries;
    o.plugin_loader = [&](const std::string& name) {
        loaded.push_back(name);
        registries.materials.add(
            "plugin-matte",
            [](const Params&) -> std::shared_ptr<Material> { return make_material_registry().create("lambert", {}); },
            TypeSpec("a plugin's matte material, no parameters"));
    };
    const LoadedScene s = parse_scene(scene, "t.json", o);
    CHECK(loaded == std::vector<std::string>{"extra"});
    CHECK(s.job.scene->object_count() == 1);
    for (const char* path : {"../x", "lib/x", "a\\\\b", "x.so", "X.SO"}) {
        const std::string bad =
            std::string(R"({"version": 1, "plugins": [")") + path + R"("], "camera": {}, "shapes": []})";
        CHECK_THAT(load_error(bad, o), Catch::Contains("is not a plugin name"));
    }
    CHECK(loaded.size() == 1);  // a path never reaches the loader
}

namespace {

// A scene whose texture "d" (an image baked from its fallback, 1024 texels around) has "lod": "auto", is the
// sky, and is seen on spheres through `material`; returns the level the loader set.
float auto_level(const std::string& textures, const std::string& material, const std::string& shapes) {
    const std::string text = R"({"version": 1,
      "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 40},
      "render": {"width": 40, "height": 30, "aa": "none", "skybox": "d"},
      "textures": [{"name": "d", "type": "image", "filename": "missing.png", "lod": "auto",
                    "fallback": {"type": "solid", "color": 0.5}, "fallback_size": [1024, 512]})" +
                             textures + R"(],
      "materials": [{"name": "m", "type": "lambert", "albedo": )" +
                             material + R"(}],
      "shapes": [)" + shapes +
                             "]}";
    const LoadedScene scene = parse_scene(text, "t.json");
    CHECK(scene.warnings.size() == 1);  // missing.png, replaced by its fallback
    const auto* levels = dynamic_cast<const LevelOfDetail*>(scene.job.whitted.environment.get());
    REQUIRE(levels != nullptr);
    return levels->lod();
}

// log2 of the texels per pixel of a 1024-texel map round a unit sphere at distance d (40 degrees, 30 pixels).
double sphere_level(double d) {
    const double pixels_per_unit = 15.0 / std::tan(20.0 * 3.14159265358979 / 180.0) / std::sqrt(d * d - 1.0);
    return std::log2(1024.0 / (2.0 * 3.14159265358979 * pixels_per_unit));
}

}  // namespace

TEST_CASE("scene loader: lod auto takes the finest level any sphere or the sky using the texture asks for", "[scene]") {
    const double sky = std::log2(1024.0 * std::tan(20.0 * 3.14159265358979 / 180.0) / 30.0);  // 3.635
    const std::string near = R"({"type": "sphere", "center": [0, 0, -2.5], "material": "m"})";
    const std::string far = R"({"type": "sphere", "material": "m", "transform": {"translate": [0, 0, -50]}})";
    // Only the sky: its level.
    CHECK(auto_level("", "0.5", far) == Approx(sky).margin(1e-4));
    // A near sphere needs a finer level than the sky (3.18 < 3.64); a far one a coarser.
    REQUIRE(sphere_level(2.5) < sky);
    REQUIRE(sphere_level(50.0) > sky);
    CHECK(auto_level("", "\"d\"", far + ", " + near) == Approx(sphere_level(2.5)).margin(1e-4));
    CHECK(auto_level("", "\"d\"", far) == Approx(sky).margin(1e-4));
    // Through a texture that uses it: a noise whose first colour is the image.
    CHECK(auto_level(R"(, {"name": "n", "type": "perlin", "color1": "d"})", "\"n\"", near) ==
          Approx(sphere_level(2.5)).margin(1e-4));
}

TEST_CASE("scene loader: a fallback stands in only for files that are missing", "[scene]") {
    const char* const text = R"({"version": 1,
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "render": {"width": 8, "height": 6},
      "textures": [{"name": "d", "type": "image", "filename": "%s",
                    "fallback": {"type": "solid", "color": [0.25, 0.5, 1]}, "fallback_size": [4, 2]}],
      "materials": [{"name": "m", "type": "lambert", "albedo": "d"}],
      "shapes": [{"type": "sphere", "material": "m"}]})";
    std::string missing(text);
    missing.replace(missing.find("%s"), 2, "nowhere.png");
    const LoadedScene scene = parse_scene(missing, "t.json");
    REQUIRE(scene.warnings.size() == 1);
    CHECK_THAT(scene.warnings[0],
               Catch::Contains("/textures/0: file 'nowhere.png' not found") && Catch::Contains("using its fallback"));
}

TEST_CASE("scene loader: a mesh file's warnings reach the scene's warnings with the shape's position", "[scene]") {
    const auto obj = test::scratch_dir("scene_loader") / "short_face.obj";
    {
        std::ofstream out(obj);
        out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n";
    }
    const std::string text = R"({"version": 1,
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "render": {"width": 8, "height": 6},
      "materials": [{"name": "m", "type": "lambert"}],
      "shapes": [{"type": "mesh", "filename": ")" +
                             obj.string() + R"(", "material": "m"}]})";
    const LoadedScene scene = parse_scene(text, "t.json");
    std::filesystem::remove(obj);
    for (const auto& w : scene.warnings) UNSCOPED_INFO(w);
    REQUIRE(scene.warnings.size() == 1);
    CHECK_THAT(scene.warnings[0], Catch::StartsWith("t.json:5:") && Catch::Contains("/shapes/0: ") &&
                                      Catch::Contains("fewer than 3 corners") && Catch::Contains("line 5"));
}
