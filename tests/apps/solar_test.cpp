// rtlab-solar-system: the scene, its filtered planet maps, the shimmer they prevent, and frame sequences.
#include "app_run.hpp"

#include <shared_data.hpp>
#include <skip.hpp>

#include <rtlab/textures/texture_param.hpp>

#include <catch2/catch.hpp>

#include "../../apps/solar_system/scene.hpp"
#include "../../apps/solar_system/sequence.hpp"

#include <cmath>
#include <cstdio>

using namespace rtlab;
using namespace rtlab::solar;
using test::run_app;

namespace {

// Nothing on the data path, not even the packages: every texture procedural.
const DataPath kNoData({}, false);

const BodyOnScreen& find(const std::vector<BodyOnScreen>& bodies, std::string_view name) {
    for (const auto& b : bodies)
        if (name == b.name) return b;
    throw Error("no body " + std::string(name));
}

float luminance(const RGB& c) {
    auto clamp = [](float x) { return std::clamp(x, 0.0f, 1.0f); };
    return 0.2126f * clamp(c.r) + 0.7152f * clamp(c.g) + 0.0722f * clamp(c.b);
}

void check_sun_and_planets(const SolarAssets& assets) {
    std::vector<BodyOnScreen> where;
    RenderJob job = make_solar_job(assets, SolarView{64, 48, 0, 1, true, 4.0f}, &where);
    job.settings.threads = 2;
    const Image image = render_job(job).image;
    const BodyOnScreen& sun = find(where, "sun");
    REQUIRE(sun.in_front);
    const int sx = static_cast<int>(sun.centre.x), sy = static_cast<int>(sun.centre.y);
    const RGB c = test::mean(image, sx - 1, sy - 1, sx + 2, sy + 2);
    CHECK(c.r > 0.8f);  // the Sun glows: its emission, no light needed
    CHECK(c.g > 0.2f);
    CHECK(c.r >= c.b);
    // Jupiter, lit by the point light inside the Sun (which does not shadow it), is brighter than the sky.
    const BodyOnScreen& jupiter = find(where, "jupiter");
    const RGB j = image.at(static_cast<int>(jupiter.centre.x), static_cast<int>(jupiter.centre.y));
    const RGB sky = test::mean(image, 0, 0, 64, 4);
    CHECK(luminance(j) > 0.2f);
    CHECK(luminance(j) > 3.0f * luminance(sky));
    CHECK(luminance(sky) < 0.2f);  // a dark star field, not a blank or white image
}

}  // namespace

TEST_CASE("solar system: the Sun is bright and the planets lit, procedural textures", "[apps]") {
    const SolarAssets assets = load_solar_assets(kNoData, false);
    CHECK_FALSE(assets.real_textures);
    CHECK(assets.note.find("procedural") != std::string::npos);
    check_sun_and_planets(assets);
}

TEST_CASE("solar system: the Sun is bright and the planets lit, the shared textures", "[apps]") {
    const auto path = test::pinned_data_path(test::DataSource::shared);
    if (!path) return test::skip(test::needs_shared("the solar system's images"));
    const SolarAssets assets = load_solar_assets(*path);
    CHECK(assets.real_textures);
    CHECK_THAT(assets.note, Catch::Matchers::Contains("from RTLAB_SHARED_DIR") &&
                                Catch::Matchers::Contains("Solar System Scope") &&
                                !Catch::Matchers::Contains("procedural"));
    check_sun_and_planets(assets);
}

TEST_CASE("solar system: the Sun is bright, the planets lit and the rings see-through, the package textures",
          "[apps]") {
    const auto path = test::pinned_data_path(test::DataSource::packages);
    if (!path) return test::skip("openuniverse-common is not installed (scripts/setup.sh)");
    const SolarAssets assets = load_solar_assets(*path);
    // The packages have no map of the Sun's surface and no star field: those two stay procedural.
    CHECK_FALSE(assets.real_textures);
    REQUIRE(assets.uses.size() == bodies().size() + 2);
    for (const AssetUse& use : assets.uses) {
        INFO(use.name);
        const bool packaged = use.name != "textures/sun.jpg" && use.name != "textures/skybox/";
        CHECK(use.file.has_value() == packaged);
        if (use.file) CHECK(use.file->source == "package openuniverse-common");
    }
    check_sun_and_planets(assets);

    // Saturn's rings: rings.jpg has no alpha, so the ring's opacity is its luminance; its inner edge is u = 0
    // (the disk's inner radius).
    REQUIRE(assets.ring);
    CHECK_FALSE(assets.ring->has_alpha());
    auto* levels = dynamic_cast<LevelOfDetail*>(assets.ring.get());
    REQUIRE(levels);
    levels->set_lod(0.0f);  // the full-resolution strip, not the level the frame above picked
    auto at = [&](float u) {
        TextureLookup l;
        l.uv = {u, 0.5f};
        return opacity(*assets.ring, l);
    };
    // The B ring (just inside the Cassini division, u about 0.5) is much more opaque than the division (0.63).
    CHECK(at(0.5f) > 0.5f);
    CHECK(at(0.635f) < 0.5f * at(0.5f));
}

TEST_CASE("planet maps: the longitude seam wraps and the poles clamp", "[apps]") {
    // The maps are made as rtlab-solar-system makes them (planet_map_params): u repeats, v stops at the poles.
    const TextureRegistry textures = make_texture_registry();
    const SolarAssets assets = load_solar_assets(kNoData, true);
    const auto& earth = assets.maps[3];
    TextureLookup a, b, pole, below_pole;
    a.uv = {0.0f, 0.5f};
    b.uv = {1.0f, 0.5f};
    CHECK(earth->eval(a).r == earth->eval(b).r);  // the same blend of the first and last columns
    pole.uv = {0.3f, 1.0f};
    below_pole.uv = {0.3f, 1.0f - 0.5f / static_cast<float>(kFallbackHeight)};  // the top row's centre
    CHECK(earth->eval(pole).g == earth->eval(below_pole).g);                    // clamped: no bottom row mixed in
    const Params p = planet_map_params(textures, 3, "");
    CHECK(p.get_string("wrap_v") == "clamp");
}

TEST_CASE("solar system: filtered maps stop a small planet shimmering", "[apps]") {
    // Earth is about 4 pixels wide at 160 x 120. Frame-to-frame change of the pixels around it, over
    // consecutive frames of a slow orbit (a 1440-frame turn): the true change (64 jittered samples per pixel,
    // unfiltered maps) against one sample per pixel with and without the filtered maps.
    // Real maps: the procedural ones are too smooth to shimmer much. The package's (a 2048-texel Earth), else
    // ../shared's; skipped when neither is there.
    auto path = test::pinned_data_path(test::DataSource::packages);
    if (!path) path = test::pinned_data_path(test::DataSource::shared);
    if (!path) return test::skip("no planet images: neither openuniverse-common nor " + test::needs_shared("they"));
    const SolarAssets assets = load_solar_assets(*path);
    REQUIRE(assets.uses[3].file);  // Earth's map is an image
    const int frames = 1440, w = 160, h = 120, count = 6;
    auto measure = [&](bool filter, PixelPattern pattern, int spp) {
        double change = 0.0;
        Image previous;
        std::vector<BodyOnScreen> previous_where;
        for (int f = 0; f < count; ++f) {
            std::vector<BodyOnScreen> where;
            RenderJob job = make_solar_job(assets, SolarView{w, h, f, frames, filter, 1.0f}, &where);
            job.settings.pattern = pattern;
            job.settings.spp = spp;
            job.settings.threads = 2;
            Image image = render_job(job).image;
            if (f > 0) {
                const BodyOnScreen& e0 = find(previous_where, "earth");
                const BodyOnScreen& e1 = find(where, "earth");
                const float r = std::max(e0.radius_pixels, e1.radius_pixels) + 1.0f;
                const int x0 = static_cast<int>(std::floor(std::min(e0.centre.x, e1.centre.x) - r));
                const int x1 = static_cast<int>(std::ceil(std::max(e0.centre.x, e1.centre.x) + r));
                const int y0 = static_cast<int>(std::floor(std::min(e0.centre.y, e1.centre.y) - r));
                const int y1 = static_cast<int>(std::ceil(std::max(e0.centre.y, e1.centre.y) + r));
                double sum = 0.0;
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x)
                        sum += std::abs(luminance(image.at(x, y)) - luminance(previous.at(x, y)));
                change += sum / ((x1 - x0) * (y1 - y0));
            }
            previous = std::move(image);
            previous_where = std::move(where);
        }
        return change / (count - 1);
    };
    const double reference = measure(false, PixelPattern::jittered, 64);
    const double unfiltered = measure(false, PixelPattern::none, 1);
    const double filtered = measure(true, PixelPattern::none, 1);
    std::printf(
        "shimmer (%s): mean frame-to-frame luminance change around Earth: reference %.5f, unfiltered %.5f, "
        "filtered %.5f\n",
        assets.uses[3].file->source.c_str(), reference, unfiltered, filtered);
    // The shimmer is the change beyond the true one: the filtered maps must remove most of it (shared maps:
    // 0.00281 -> 0.00016; package maps: 0.00202 -> 0.00067), and come closer to the true change.
    CHECK(unfiltered - reference > 2.0 * std::abs(filtered - reference));
    CHECK(std::abs(filtered - reference) < std::abs(unfiltered - reference));
}

TEST_CASE("frame ranges and numbered files", "[apps]") {
    CHECK(parse_frame_range("", 10).first == 0);
    CHECK(parse_frame_range("", 10).last == 10);
    CHECK(parse_frame_range("3:7", 10).first == 3);
    CHECK(parse_frame_range("3:7", 10).last == 7);
    CHECK(parse_frame_range("0:10", 10).last == 10);
    CHECK_THROWS_WITH(parse_frame_range("7:3", 10), Catch::Contains("0 <= A < B <= 10"));
    CHECK_THROWS_WITH(parse_frame_range("0:11", 10), Catch::Contains("0 <= A < B <= 10"));
    CHECK_THROWS_WITH(parse_frame_range("-1:3", 10), Catch::Contains("0 <= A < B"));
    CHECK_THROWS_WITH(parse_frame_range("3", 10), Catch::Contains("A:B"));
    CHECK_THROWS_WITH(parse_frame_range("a:b", 10), Catch::Contains("A:B"));
    CHECK(numbered_path("out/solar.png", 7) == std::filesystem::path("out/solar-0007.png"));
    CHECK(numbered_path("solar.exr", 12345) == std::filesystem::path("solar-12345.exr"));
}

TEST_CASE("rtlab-solar-system --frames --frame-range renders just those frames, as the scene function does", "[apps]") {
    const auto dir = test::scratch_dir("apps_solar");
    for (int f = 0; f < 3; ++f) std::filesystem::remove(numbered_path(dir / "solar.pfm", f));
    const auto run =
        run_app(SOLAR_EXE,
                "--procedural --width 64 --height 48 --threads 2 --quiet --frames 3 --frame-range 1:3 -o '" +
                    (dir / "solar.pfm").string() + "'",
                dir);
    REQUIRE(run.status == 0);
    CHECK_FALSE(std::filesystem::exists(dir / "solar-0000.pfm"));
    REQUIRE(std::filesystem::exists(dir / "solar-0001.pfm"));
    REQUIRE(std::filesystem::exists(dir / "solar-0002.pfm"));
    const Image one = read_pfm(dir / "solar-0001.pfm");
    const Image two = read_pfm(dir / "solar-0002.pfm");
    CHECK_FALSE(test::same_pixels(one, two));  // the camera moved
    const SolarAssets assets = load_solar_assets(kNoData, true);
    CHECK(test::same_pixels(one, render_job(make_solar_job(assets, SolarView{64, 48, 1, 3, true, 4.0f})).image));
}
