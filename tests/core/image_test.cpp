#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/core/srgb.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"

#include <fstream>
#include <limits>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
Image gradient(int w, int h, float scale) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.at(x, y) = RGB(scale * x / (w - 1), scale * y / (h - 1), scale * 0.5f * (x + y) / (w + h));
    return img;
}

void write_text(const std::filesystem::path& p, const std::string& s) { std::ofstream(p, std::ios::binary) << s; }

const auto dir = test::scratch_dir("core_image");
}  // namespace

TEST_CASE("sRGB transfer function round-trips every 8-bit code", "[image]") {
    for (int c = 0; c < 256; ++c) REQUIRE(srgb_encode_8bit(srgb_decode_8bit(static_cast<std::uint8_t>(c))) == c);
    CHECK(srgb_encode(-1.0f) == 0.0f);
    CHECK(srgb_encode(std::numeric_limits<float>::quiet_NaN()) == 0.0f);
    CHECK(srgb_encode(2.0f) == 1.0f);
    CHECK(srgb_encode(0.18f) == Approx(0.4613561f).epsilon(1e-5));
}

TEST_CASE("PFM round trip is exact even for values far outside the unit range", "[image]") {
    Image img = gradient(7, 5, 1000.0f);
    img.at(0, 0) = RGB(1e-6f, 1e6f, -3.0f);
    write_image(img, dir / "g.pfm");
    const Image back = read_image(dir / "g.pfm");
    REQUIRE(back.width() == 7);
    REQUIRE(back.height() == 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) REQUIRE(back.at(x, y) == img.at(x, y));
}

TEST_CASE("PNG round trip is within half an 8-bit sRGB step", "[image]") {
    const Image img = gradient(16, 9, 1.0f);
    write_image(img, dir / "g.png");
    const Image back = read_image(dir / "g.png");
    REQUIRE(back.width() == 16);
    REQUIRE(back.height() == 9);
    float worst = 0.0f;
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 16; ++x)
            for (int k = 0; k < 3; ++k)
                worst = std::max(worst, std::abs(srgb_encode(back.at(x, y)[k]) - srgb_encode(img.at(x, y)[k])));
    CHECK(worst <= 0.5f / 255.0f + 1e-6f);
    // Out-of-range and NaN values are clamped, not wrapped.
    Image clamp(2, 1);
    clamp.at(0, 0) = RGB(5.0f, -1.0f, std::numeric_limits<float>::quiet_NaN());
    write_png(clamp, dir / "c.png");
    const Image c = read_image(dir / "c.png");
    CHECK(c.at(0, 0) == RGB(1.0f, 0.0f, 0.0f));
}

TEST_CASE("RGBA PNG keeps every 8-bit alpha code exactly and never sRGB-decodes it", "[image]") {
    // 256 x 1: alpha code c at column c, colour 0.2 everywhere.
    Image img(256, 1, RGB(0.2f));
    img.add_alpha();
    for (int c = 0; c < 256; ++c) img.alpha_at(c, 0) = static_cast<float>(c) / 255.0f;
    write_png(img, dir / "alpha.png");
    for (ColorEncoding encoding : {ColorEncoding::srgb, ColorEncoding::linear}) {
        const Image back = read_image(dir / "alpha.png", encoding);
        REQUIRE(back.has_alpha());
        REQUIRE(back.alphas().size() == 256);
        int wrong = 0;
        for (int c = 0; c < 256; ++c) wrong += back.alpha(c, 0) == static_cast<float>(c) / 255.0f ? 0 : 1;
        CHECK(wrong == 0);
        CHECK(back.alpha(0, 0) == 0.0f);
        CHECK(back.alpha(255, 0) == 1.0f);
        // Colour is still decoded as asked; alpha code 128 is 128 / 255, not the sRGB decode 0.216.
        const float expected = encoding == ColorEncoding::srgb ? 0.2f : srgb_encode(0.2f);
        CHECK(back.at(128, 0).r == Approx(expected).margin(0.003f));
        CHECK(back.alpha(128, 0) == Approx(0.50196f).epsilon(1e-4));
    }
    // Out-of-range and NaN alpha are clamped to [0, 1] on writing; rounding is to the nearest code.
    Image odd(5, 1);
    odd.add_alpha(0.25f);
    odd.alpha_at(0, 0) = -2.0f;
    odd.alpha_at(1, 0) = 7.0f;
    odd.alpha_at(2, 0) = std::numeric_limits<float>::quiet_NaN();
    odd.alpha_at(3, 0) = 0.5f / 255.0f + 1e-4f;  // just past half a code: rounds up to code 1
    write_png(odd, dir / "odd_alpha.png");
    const Image o = read_image(dir / "odd_alpha.png");
    CHECK(o.alpha(0, 0) == 0.0f);
    CHECK(o.alpha(1, 0) == 1.0f);
    CHECK(o.alpha(2, 0) == 0.0f);
    CHECK(o.alpha(3, 0) == 1.0f / 255.0f);
    CHECK(o.alpha(4, 0) == 64.0f / 255.0f);  // 0.25 * 255 = 63.75 -> 64
}

TEST_CASE("images without alpha have alpha 1 everywhere and keep the old API", "[image]") {
    Image img(3, 2, RGB(0.5f));
    CHECK_FALSE(img.has_alpha());
    CHECK(img.alphas().empty());
    CHECK(img.alpha(2, 1) == 1.0f);
    img.add_alpha(0.25f);
    REQUIRE(img.has_alpha());
    CHECK(img.alpha(2, 1) == 0.25f);
    img.alpha_at(2, 1) = 0.75f;
    img.add_alpha(0.0f);  // an existing plane is kept
    CHECK(img.alpha(2, 1) == 0.75f);
    CHECK(img.alpha(0, 0) == 0.25f);
    CHECK(img.at(2, 1) == RGB(0.5f));
    // RGB PNG, HDR and PFM files read back without an alpha plane; writing an RGBA image to them drops alpha.
    write_image(Image(2, 2, RGB(0.5f)), dir / "rgb.png");
    CHECK_FALSE(read_image(dir / "rgb.png").has_alpha());
    for (const char* name : {"a.hdr", "a.pfm"}) {
        write_image(img, dir / name);
        const Image back = read_image(dir / name);
        CHECK_FALSE(back.has_alpha());
        CHECK(back.alpha(1, 1) == 1.0f);
    }
}

TEST_CASE("HDR round trip is within RGBE's relative precision", "[image]") {
    const Image img = gradient(8, 8, 5000.0f);
    write_image(img, dir / "g.hdr");
    const Image back = read_image(dir / "g.hdr");
    REQUIRE(back.width() == 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const float m = img.at(x, y).max_component();
            for (int k = 0; k < 3; ++k) REQUIRE(std::abs(back.at(x, y)[k] - img.at(x, y)[k]) <= m / 128.0f + 1e-6f);
        }
}

TEST_CASE("unreadable and corrupt image files raise errors naming the file", "[image]") {
    CHECK_THROWS_AS(read_image(dir / "missing.png"), Error);
    CHECK_THROWS_WITH(read_image(dir / "missing.png"), Contains("missing.png"));
    CHECK_THROWS_WITH(read_image(dir), Contains("directory"));
    write_text(dir / "empty.png", "");
    CHECK_THROWS_WITH(read_image(dir / "empty.png"), Contains("empty.png") && Contains("empty file"));
    write_text(dir / "garbage.png", "this is not an image at all");
    CHECK_THROWS_WITH(read_image(dir / "garbage.png"), Contains("garbage.png") && Contains("cannot decode"));
    // A real PNG cut in half.
    write_png(gradient(32, 32, 1.0f), dir / "whole.png");
    auto bytes = read_binary_file(dir / "whole.png");
    bytes.resize(bytes.size() / 2);
    write_binary_file(dir / "half.png", bytes);
    CHECK_THROWS_WITH(read_image(dir / "half.png"), Contains("half.png"));
    write_text(dir / "trunc.pfm", "PF\n4 4\n-1.0\n0123");
    CHECK_THROWS_WITH(read_image(dir / "trunc.pfm"), Contains("truncated PFM raster"));
    write_text(dir / "huge.pfm", "PF\n100000000 100000000\n-1.0\n");
    CHECK_THROWS_WITH(read_image(dir / "huge.pfm"), Contains("unsupported size"));
    write_text(dir / "bad.pfm", "PF\nfour 4\n-1.0\n");
    CHECK_THROWS_WITH(read_image(dir / "bad.pfm"), Contains("bad width"));
    write_text(dir / "zero.pfm", "PF\n4 4\n0\n");
    CHECK_THROWS_WITH(read_image(dir / "zero.pfm"), Contains("scale"));
}

TEST_CASE("unwritable paths and unknown extensions raise errors", "[image]") {
    const Image img(2, 2);
    CHECK_THROWS_WITH(write_image(img, dir / "no_such_dir" / "x.png"), Contains("x.png"));
    CHECK_THROWS_WITH(write_image(img, dir / "x.bmp"), Contains("unknown image extension"));
    CHECK_THROWS_WITH(write_image(Image{}, dir / "x.png"), Contains("empty image"));
    CHECK_THROWS_AS(Image(-1, 2), Error);
}
