#include <rtlab/core/error.hpp>
#include <rtlab/core/sample_hash.hpp>
#include <rtlab/core/srgb.hpp>
#include <rtlab/render/exr.hpp>
#include <rtlab/render/image_output.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <unistd.h>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

/// A fresh empty folder for one test.
fs::path scratch(const char* name) {
    // The process id keeps concurrent test runs (ctest -j, other checkouts) apart.
    const fs::path dir =
        fs::temp_directory_path() / ("rtlab_render_output_" + std::string(name) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::size_t files_in(const fs::path& dir) {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

/// HDR values over six orders of magnitude, some above 1, and exact zeros.
Image test_image(int w = 37, int h = 23) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const SampleKey k{4, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 0, 0};
            auto v = [&](std::uint32_t d) { return std::pow(10.0f, 6.0f * sample_uniform(k, d) - 4.0f); };
            img.at(x, y) = (x + y) % 11 == 0 ? RGB(0.0f) : RGB(v(0), v(1), v(2));
        }
    return img;
}

}  // namespace

TEST_CASE("pfm and exr round-trip float pixels exactly", "[output]") {
    const fs::path dir = scratch("float");
    const Image img = test_image();
    for (const char* name : {"a.pfm", "a.exr", "A.EXR"}) {
        INFO(name);
        write_render_output(img, dir / name);
        const Image back = fs::path(name).extension() == ".pfm" ? read_pfm(dir / name) : read_exr(dir / name);
        REQUIRE(back.width() == img.width());
        REQUIRE(back.height() == img.height());
        int differ = 0;
        for (std::size_t i = 0; i < img.pixel_count(); ++i) differ += !(back.pixels()[i] == img.pixels()[i]);
        CHECK(differ == 0);
    }
    // Nothing but the three images: no temporary file is left behind.
    CHECK(files_in(dir) == 3);
    fs::remove_all(dir);
}

TEST_CASE("exr keeps NaN infinity and negative values", "[output]") {
    const fs::path dir = scratch("exr_special");
    Image img(3, 1);
    img.at(0, 0) = RGB(std::numeric_limits<float>::quiet_NaN(), 1.0f, 2.0f);
    img.at(1, 0) = RGB(std::numeric_limits<float>::infinity(), -3.5f, 1e-30f);
    img.at(2, 0) = RGB(3e38f, 0.0f, -0.0f);
    write_exr(img, dir / "s.exr");
    const Image back = read_exr(dir / "s.exr");
    CHECK(std::isnan(back.at(0, 0).r));
    CHECK(back.at(1, 0).r == std::numeric_limits<float>::infinity());
    CHECK(back.at(1, 0).g == -3.5f);
    CHECK(back.at(1, 0).b == 1e-30f);
    CHECK(back.at(2, 0).r == 3e38f);
    fs::remove_all(dir);
}

TEST_CASE("hdr round-trips within RGBE precision", "[output]") {
    const fs::path dir = scratch("hdr");
    const Image img = test_image();
    write_render_output(img, dir / "a.hdr");
    const Image back = read_image(dir / "a.hdr");
    REQUIRE(back.width() == img.width());
    int bad = 0;
    for (std::size_t i = 0; i < img.pixel_count(); ++i) {
        const RGB a = img.pixels()[i], b = back.pixels()[i];
        // RGBE shares one exponent: each component is exact to 1/256 of the largest (plus rounding).
        const float tol = a.max_component() / 128.0f;
        for (int c = 0; c < 3; ++c) bad += std::abs(a[c] - b[c]) > tol;
    }
    CHECK(bad == 0);
    fs::remove_all(dir);
}

TEST_CASE("png is clamped with none and tone-mapped with an operator then sRGB encoded", "[output]") {
    const fs::path dir = scratch("png");
    Image img = test_image();
    img.at(1, 0) = RGB(std::numeric_limits<float>::quiet_NaN(), -1.0f, 0.5f);
    write_render_output(img, dir / "none.png", make_tone_operator(make_tone_registry(), "none").get());
    const Image clamped = read_image(dir / "none.png", ColorEncoding::linear);
    int bad = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const float v = img.at(x, y)[c];
                const float expect = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
                // Read back as the 8-bit code / 255: that must be the sRGB code of the clamped value.
                bad += std::lround(clamped.at(x, y)[c] * 255.0f) != srgb_encode_8bit(expect);
            }
    CHECK(bad == 0);

    const ToneRegistry registry = make_tone_registry();
    const auto reinhard = make_tone_operator(registry, "reinhard");
    REQUIRE(reinhard);
    ToneReport report;
    write_render_output(img, dir / "reinhard.png", reinhard.get(), &report);
    CHECK(report.invalid_pixels == 1);
    const Image display = reinhard->apply(img);
    const Image mapped = read_image(dir / "reinhard.png", ColorEncoding::linear);
    bad = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            for (int c = 0; c < 3; ++c)
                bad += std::lround(mapped.at(x, y)[c] * 255.0f) != srgb_encode_8bit(display.at(x, y)[c]);
    CHECK(bad == 0);
    // Reinhard is not a clamp: bright pixels are compressed, not saturated.
    CHECK_FALSE(clamped.at(5, 5) == mapped.at(5, 5));
    fs::remove_all(dir);
}

TEST_CASE("a failed write leaves nothing under the asked name nor a temporary file", "[output]") {
    using Catch::Matchers::Contains;
    const fs::path dir = scratch("fail");
    const Image img = test_image(4, 4);
    // The target is a folder: the image is written to the temporary file, then renaming fails.
    fs::create_directory(dir / "taken.exr");
    CHECK_THROWS_WITH(write_render_output(img, dir / "taken.exr"), Contains("taken.exr") && !Contains(".tmp-"));
    CHECK(fs::is_directory(dir / "taken.exr"));
    CHECK(files_in(dir) == 1);
    // A folder that does not exist: the writer fails, and the message names the asked file.
    CHECK_THROWS_WITH(write_render_output(img, dir / "missing" / "x.pfm"),
                      Contains("missing/x.pfm") && !Contains(".tmp-"));
    CHECK(files_in(dir) == 1);
    // An existing image stays as it was when writing over it fails.
    { std::ofstream(dir / "old.png") << "old"; }
    CHECK_THROWS_WITH(write_render_output(Image(), dir / "old.png"), Contains("empty"));
    CHECK(fs::file_size(dir / "old.png") == 3);
    CHECK_THROWS_WITH(write_render_output(img, dir / "x.jpg"), Contains(".png, .hdr, .pfm, .exr"));
    CHECK(files_in(dir) == 2);
    // Unknown tone operators and parameters are errors.
    CHECK_THROWS_WITH(make_tone_operator(make_tone_registry(), "fancy"), Contains("fancy"));
    Params p;
    p.set("key", 0.5);
    CHECK_THROWS_WITH(make_tone_operator(make_tone_registry(), "none", p), Contains("key"));
    // A successful write replaces an existing file.
    write_render_output(img, dir / "old.png");
    CHECK(fs::file_size(dir / "old.png") > 3);
    CHECK(files_in(dir) == 2);
    fs::remove_all(dir);
}

TEST_CASE("reading a file that is not an exr names it", "[output]") {
    using Catch::Matchers::Contains;
    const fs::path dir = scratch("bad_exr");
    { std::ofstream(dir / "bad.exr") << "this is not an EXR file"; }
    CHECK_THROWS_WITH(read_exr(dir / "bad.exr"), Contains("bad.exr"));
    CHECK_THROWS_WITH(read_exr(dir / "none.exr"), Contains("none.exr"));
    CHECK_THROWS_WITH(write_exr(Image(), dir / "e.exr"), Contains("empty"));
    fs::remove_all(dir);
}
