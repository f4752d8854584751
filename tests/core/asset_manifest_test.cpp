// The package files the manifest (data/assets.tsv) names hold what it says: each image its width x height.
// (The meshes' triangle counts are checked where meshes load: tests/geometry/real_models_test.cpp.)
#include "rtlab/core/asset_manifest.hpp"

#include <catch2/catch.hpp>
#include <shared_data.hpp>
#include <skip.hpp>

#include "rtlab/core/image.hpp"

using namespace rtlab;

TEST_CASE("the data packages' images have the sizes the manifest gives", "[data_path]") {
    int checked = 0;
    for (const AssetEntry& e : asset_manifest()) {
        if (!e.from_package() || e.expected.find('x') == std::string::npos) continue;
        // OpenEXR maps are read by rtlab::render (tests/render/environment_files_test.cpp checks them).
        if (e.file.extension() == ".exr") continue;
        if (!std::filesystem::is_regular_file(e.file)) continue;
        const Image image = read_image(e.file, ColorEncoding::srgb);
        INFO(e.file.string());
        CHECK(std::to_string(image.width()) + "x" + std::to_string(image.height()) == e.expected);
        ++checked;
    }
    if (checked == 0) return test::skip("no data package is installed (scripts/setup.sh installs them)");
}

TEST_CASE("the ring strip of openuniverse-common has its inner edge at u = 0", "[data_path]") {
    // rings.jpg has no alpha: its luminance is the ring's opacity. Read across (u, left to right): the dim C
    // ring, the broad bright B ring, the dark Cassini division, then the A ring with the thin Encke gap near
    // its outer edge. The B ring lies inside the Cassini division and is the wider: so the wide bright band is
    // on the side of the inner edge, here the left (u = 0), which is where a disk's u starts (its inner radius).
    const std::filesystem::path file = "/usr/share/openuniverse/textures/rings.jpg";
    if (!std::filesystem::is_regular_file(file)) return test::skip("openuniverse-common is not installed");
    const Image strip = read_image(file, ColorEncoding::srgb);
    std::vector<float> column(static_cast<std::size_t>(strip.width()));
    for (int x = 0; x < strip.width(); ++x) {
        float sum = 0.0f;
        for (int y = 0; y < strip.height(); ++y) {
            const RGB c = strip.at(x, y);
            sum += (c.r + c.g + c.b) / 3.0f;
        }
        column[static_cast<std::size_t>(x)] = sum / static_cast<float>(strip.height());
    }
    // The Cassini division: the widest run of dark columns (below half the brightest) away from the ends.
    float brightest = 0.0f;
    for (float c : column) brightest = std::max(brightest, c);
    int best_start = 0, best_length = 0;
    const int margin = strip.width() / 10;
    for (int x = margin; x < strip.width() - margin;) {
        int end = x;
        while (end < strip.width() - margin && column[static_cast<std::size_t>(end)] < 0.5f * brightest) ++end;
        if (end - x > best_length) best_start = x, best_length = end - x;
        x = std::max(end, x + 1);
    }
    REQUIRE(best_length >= strip.width() / 40);  // a clear gap, several columns wide
    const int inner_side = best_start, outer_side = strip.width() - (best_start + best_length);
    INFO("Cassini division at columns " << best_start << ".." << best_start + best_length);
    CHECK(inner_side > outer_side);  // the wider B ring is on the left: u = 0 is the inner edge
    // And its opacity is not flat: the division lets light through, the B ring much less.
    CHECK(column[static_cast<std::size_t>(best_start + best_length / 2)] < 0.5f * column[strip.width() / 3]);
}
