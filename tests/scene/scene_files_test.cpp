// Every scene in scenes/ loads and renders, at 64 x 48, the image committed in tests/scene/reference/ within
// kSceneTolerance. Set RTLAB_UPDATE_REFERENCES=1 to rewrite the references (then look at them). A scene that
// reads data is rendered once per data source, its data root pinned to that source alone, against
// reference/<name>.<source>.pfm: the package bunny (69,666 triangles) is not the shared one (69,451), and the
// OpenUniverse maps are not the Solar System Scope ones.
#include <rtlab/core/image.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <catch2/catch.hpp>
#include <shared_data.hpp>
#include <skip.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = RTLAB_SOURCE_DIR;

// Root-mean-square difference over all channels divided by the reference's mean: a scale-free error. A render
// of the same scene by the same code differs by 0 (the renderer is deterministic); 2% leaves room for another
// compiler's rounding, while a black image scores 1 or more and a flat image of the reference's mean colour
// scores the reference's relative standard deviation (above 0.2 for every scene here, checked below).
constexpr double kSceneTolerance = 0.02;

double relative_rms(const Image& image, const Image& reference) {
    REQUIRE(image.width() == reference.width());
    REQUIRE(image.height() == reference.height());
    double sum_sq = 0.0, sum_ref = 0.0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const RGB a = image.at(x, y), b = reference.at(x, y);
            for (int c = 0; c < 3; ++c) {
                const double d = static_cast<double>(a[c]) - static_cast<double>(b[c]);
                sum_sq += std::isfinite(d) ? d * d : 1e30;
                sum_ref += std::abs(static_cast<double>(b[c]));
            }
        }
    const double n = 3.0 * image.width() * image.height();
    return std::sqrt(sum_sq / n) / std::max(sum_ref / n, 1e-12);
}

Image flat_like(const Image& reference) {
    RGB mean;
    for (int y = 0; y < reference.height(); ++y)
        for (int x = 0; x < reference.width(); ++x) mean += reference.at(x, y);
    mean = mean * (1.0f / static_cast<float>(reference.width() * reference.height()));
    Image flat(reference.width(), reference.height());
    for (int y = 0; y < flat.height(); ++y)
        for (int x = 0; x < flat.width(); ++x) flat.at(x, y) = mean;
    return flat;
}

// `source`: the scene reads data, from that source alone (skipped when it is absent).
void check_scene(const std::string& name, std::optional<test::DataSource> source = std::nullopt) {
    SceneLoadOptions options;
    options.use_environment = false;
    std::string reference_name = name;
    if (source) {
        const auto root = test::data_root(*source);
        if (!root) return test::skip("scenes/" + name + ".json: no " + test::source_name(*source) + " data");
        options.data_dirs = {*root};
        reference_name += std::string(".") + test::source_name(*source);
    }
    options.overrides.width = 64;
    options.overrides.height = 48;
    const LoadedScene scene = load_scene(kSource / "scenes" / (name + ".json"), options);
    const Image image = render_job(scene.job).image;
    const fs::path reference_file = kSource / "tests/scene/reference" / (reference_name + ".pfm");
    if (std::getenv("RTLAB_UPDATE_REFERENCES")) {
        write_image(image, reference_file);
        WARN("wrote " + reference_file.string());
    }
    const Image reference = read_image(reference_file, ColorEncoding::linear);
    const double error = relative_rms(image, reference);
    INFO(name << ": relative RMS difference " << error);
    CHECK(error <= kSceneTolerance);
    // The comparison can fail: a black image and a flat one of the right mean colour are far outside it.
    CHECK(relative_rms(Image(64, 48), reference) > 0.5);
    CHECK(relative_rms(flat_like(reference), reference) > 10 * kSceneTolerance);
}

}  // namespace

TEST_CASE("scene file analytic.json matches its reference image", "[scene_files]") { check_scene("analytic"); }
TEST_CASE("scene file whitted.json matches its reference image", "[scene_files]") { check_scene("whitted"); }
TEST_CASE("scene file bunny.json matches its reference image with the shared data", "[scene_files]") {
    check_scene("bunny", test::DataSource::shared);
}
TEST_CASE("scene file bunny.json matches its reference image with the package data", "[scene_files]") {
    check_scene("bunny", test::DataSource::packages);
}
TEST_CASE("scene file solar_system.json matches its reference image with the shared data", "[scene_files]") {
    check_scene("solar_system", test::DataSource::shared);
}
TEST_CASE("scene file solar_system.json matches its reference image with the package data", "[scene_files]") {
    check_scene("solar_system", test::DataSource::packages);
}

TEST_CASE("scene file cornell_box.json shows the red wall on the left and the green on the right", "[scene_files]") {
    // Path traced small and short (32 x 32, 8 samples, 3 bounces): the walls' colours are plain at any noise.
    SceneLoadOptions options;
    options.use_environment = false;
    options.overrides.width = options.overrides.height = 32;
    options.overrides.spp = 8;
    options.overrides.max_depth = 3;
    const LoadedScene scene = load_scene(kSource / "scenes/cornell_box.json", options);
    REQUIRE(scene.job.integrator == IntegratorKind::path);
    const Image image = render_job(scene.job).image;
    RGB left, right;
    for (int y = 8; y < 24; ++y)
        for (int x = 0; x < 3; ++x) {
            left += image.at(x, y);
            right += image.at(31 - x, y);
        }
    INFO("left " << left.r << " " << left.g << " " << left.b << ", right " << right.r << " " << right.g << " "
                 << right.b);
    CHECK(left.r > 3.0f * left.g);
    CHECK(right.g > 2.0f * right.r);
    CHECK(left.r > 0.5f);
}

TEST_CASE("scene file bunny_envmap.json: the map's sun from the front right casts the bunny's shadow to the left",
          "[scene_files]") {
    // Path traced small and short (64 x 48, 16 samples, 3 bounces) from the packages' bunny and city.exr: the floor
    // left of the bunny lies in its shadow, the floor right of it in the sun (the orientation of docs/scene-format.md).
    const auto root = test::data_root(test::DataSource::packages);
    if (!root) return test::skip("scenes/bunny_envmap.json: the data packages are not installed");
    SceneLoadOptions options;
    options.use_environment = false;
    options.data_dirs = {*root};
    options.overrides.width = 64;
    options.overrides.height = 48;
    options.overrides.spp = 16;
    options.overrides.max_depth = 3;
    const LoadedScene scene = load_scene(kSource / "scenes/bunny_envmap.json", options);
    REQUIRE(scene.job.environment);
    const Image image = render_job(scene.job).image;
    double shadow = 0.0, sunlit = 0.0;
    for (int y = 33; y < 39; ++y)
        for (int x = 0; x < 16; ++x) {
            shadow += image.at(8 + x, y).luminance();
            sunlit += image.at(44 + x, y).luminance();
        }
    INFO("floor left of the bunny " << shadow / 96 << ", right of it " << sunlit / 96);
    CHECK(shadow < 0.75 * sunlit);
    CHECK(sunlit / 96 > 0.5);
}
