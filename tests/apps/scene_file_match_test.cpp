// Each course app and its scene file in scenes/ describe the same scene: rendered at a small size with the same
// settings, the app's job and the loaded file give byte-identical linear images (every float of every pixel).
#include "app_run.hpp"

#include <rtlab/geometry/mesh_io.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/scene_loader.hpp>
#include <shared_data.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "../../apps/bunny/scene.hpp"
#include "../../apps/whitted/scene.hpp"

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 64, kHeight = 48;

LoadedScene load_course_scene(const std::string& name, std::vector<fs::path> data_dirs = {}) {
    SceneLoadOptions options;
    options.data_dirs = std::move(data_dirs);
    options.use_environment = false;
    options.overrides.width = kWidth;
    options.overrides.height = kHeight;
    return load_scene(fs::path(RTLAB_SOURCE_DIR) / "scenes" / (name + ".json"), options);
}

// The settings that pick the samples must already agree (they come from the app and the file); only the
// thread count, which does not change the image, is set here for speed.
void require_same_settings(RenderJob& app, RenderJob& file) {
    CHECK(app.settings.pattern == file.settings.pattern);
    CHECK(app.settings.spp == file.settings.spp);
    CHECK(app.settings.seed == file.settings.seed);
    CHECK(app.settings.adaptive.max_depth == file.settings.adaptive.max_depth);
    CHECK(app.settings.adaptive.threshold == file.settings.adaptive.threshold);
    CHECK(app.whitted.max_depth == file.whitted.max_depth);
    CHECK(app.whitted.convention == file.whitted.convention);
    REQUIRE(app.scene->objects().size() == file.scene->objects().size());
    REQUIRE(app.lights.size() == file.lights.size());
    app.settings.threads = file.settings.threads = 2;
}

// Pixels whose three floats are not bit for bit the same (-0 and 0 differ; a NaN equals itself).
int differing_pixels(const Image& a, const Image& b) {
    REQUIRE(a.width() == b.width());
    REQUIRE(a.height() == b.height());
    int n = 0;
    for (std::size_t i = 0; i < a.pixel_count(); ++i)
        n += std::memcmp(&a.pixels()[i], &b.pixels()[i], sizeof(RGB)) != 0 ? 1 : 0;
    return n;
}

// Not black, not flat: a picture, so that matching cannot come from two empty scenes.
void require_a_picture(const Image& image) {
    float lo_r = 1e30f, hi_r = -1e30f, lo_b = 1e30f, hi_b = -1e30f;
    for (std::size_t i = 0; i < image.pixel_count(); ++i) {
        const RGB c = image.pixels()[i];
        lo_r = std::min(lo_r, c.r), hi_r = std::max(hi_r, c.r);
        lo_b = std::min(lo_b, c.b), hi_b = std::max(hi_b, c.b);
    }
    CHECK(hi_r - lo_r > 0.3f);
    CHECK(hi_b - lo_b > 0.3f);
}

}  // namespace

TEST_CASE("scene files: scenes/whitted.json renders byte-identical to rtlab-whitted", "[apps]") {
    RenderJob app = whitted::make_whitted_job(kWidth, kHeight);
    LoadedScene file = load_course_scene("whitted");
    require_same_settings(app, file.job);
    const Image a = render_job(app).image, b = render_job(file.job).image;
    require_a_picture(a);
    CHECK(differing_pixels(a, b) == 0);
}

TEST_CASE("scene files: scenes/bunny.json renders byte-identical to rtlab-bunny", "[apps]") {
    const auto shared = test::shared_dir();
    if (!shared) {
        WARN("skipped: rtlab-bunny's mesh (models/stanford-bunny.obj) needs ../shared; set RTLAB_SHARED_DIR");
        return;
    }
    // As rtlab-bunny loads it (apps/bunny/main.cpp).
    const auto mesh =
        std::make_shared<const TriangleMesh>(with_smooth_normals(load_mesh(*shared / bunny::kDefaultMesh)));
    RenderJob app = bunny::make_bunny_job(mesh, "diffuse", kWidth, kHeight);
    LoadedScene file = load_course_scene("bunny", {*shared / "models"});
    require_same_settings(app, file.job);
    const Image a = render_job(app).image, b = render_job(file.job).image;
    require_a_picture(a);
    CHECK(differing_pixels(a, b) == 0);
}
