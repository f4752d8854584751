#include <rtlab/core/image.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/textures/image_texture.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"

#include <cmath>

using namespace rtlab;

namespace {
const auto dir = test::scratch_dir("textures_alpha");

float code(int c) { return static_cast<float>(c) / 255.0f; }

// A 2x2 RGBA PNG: alpha codes 0 255 on the top row, 102 204 below; dark colours, so that alpha and
// colour cannot be mistaken for each other.
std::filesystem::path rgba_2x2() {
    Image img(2, 2, RGB(0.05f, 0.1f, 0.02f));
    img.add_alpha();
    img.alpha_at(0, 0) = code(0);
    img.alpha_at(1, 0) = code(255);
    img.alpha_at(0, 1) = code(102);
    img.alpha_at(1, 1) = code(204);
    const auto path = dir / "rgba_2x2.png";
    write_png(img, path);
    return path;
}

// A 3x1 RGBA row with alpha codes 51 153 255.
std::shared_ptr<const Image> rgba_row3() {
    auto img = std::make_shared<Image>(3, 1, RGB(1.0f));
    img->add_alpha();
    for (int x = 0; x < 3; ++x) img->alpha_at(x, 0) = code(51 + 102 * x);
    return img;
}

TextureLookup at(float u, float v) { return TextureLookup{{u, v}, {}, {}}; }
}  // namespace

TEST_CASE("an RGBA image texture gives the file's alpha with bilinear weights", "[alpha]") {
    const auto t = ImageTexture::load(rgba_2x2(), {.wrap = WrapMode::clamp});
    REQUIRE(t->has_alpha());
    // Texel centres give the stored codes exactly, whatever the sRGB decoding of the colour.
    CHECK(t->alpha(at(0.25f, 0.75f)) == code(0));
    CHECK(t->alpha(at(0.75f, 0.75f)) == code(255));
    CHECK(t->alpha(at(0.25f, 0.25f)) == code(102));
    CHECK(t->alpha(at(0.75f, 0.25f)) == code(204));
    // The same blends as the colour: the centre is the mean; (0.375, 0.75) is 0.75 a00 + 0.25 a10.
    CHECK(t->alpha(at(0.5f, 0.5f)) == Approx((0.0f + 1.0f + code(102) + code(204)) / 4.0f).epsilon(1e-6));
    CHECK(t->alpha(at(0.375f, 0.75f)) == Approx(0.25f).epsilon(1e-6));
    // (0.4, 0.6): weights 0.49 0.21 0.21 0.09 as in the colour test.
    CHECK(t->alpha(at(0.4f, 0.6f)) == Approx(0.21f + 0.21f * code(102) + 0.09f * code(204)).epsilon(1e-5));
    // Clamp beyond the edges; the colour is unaffected by alpha.
    CHECK(t->alpha(at(-3.0f, 0.75f)) == 0.0f);
    CHECK(t->alpha(at(0.75f, -2.0f)) == code(204));
    CHECK(t->eval(at(0.25f, 0.75f)).g == Approx(0.1f).margin(0.002f));
    // Non-finite uv: nothing there, black and transparent.
    CHECK(t->alpha(at(std::nanf(""), 0.5f)) == 0.0f);
    CHECK(t->alpha(at(0.5f, INFINITY)) == 0.0f);
}

TEST_CASE("alpha follows the wrap modes and nearest filtering like the colour", "[alpha]") {
    const auto img = rgba_row3();
    const ImageTexture repeat(img, {.wrap = WrapMode::repeat, .filter = ImageFilter::nearest});
    const ImageTexture clamp(img, {.wrap = WrapMode::clamp, .filter = ImageFilter::nearest});
    const ImageTexture mirror(img, {.wrap = WrapMode::mirror, .filter = ImageFilter::nearest});
    // Texel x beyond the image reads  repeat: x mod 3; clamp: clamp(x, 0, 2); mirror: period 6.
    struct Row {
        int x, repeat, clamp, mirror;
    };
    for (const Row& r : {Row{-1, 2, 0, 0}, Row{-2, 1, 0, 1}, Row{-3, 0, 0, 2}, Row{-4, 2, 0, 2}, Row{3, 0, 2, 2},
                         Row{4, 1, 2, 1}, Row{5, 2, 2, 0}, Row{6, 0, 2, 0}, Row{1, 1, 1, 1}}) {
        const float u = (static_cast<float>(r.x) + 0.5f) / 3.0f;
        INFO("texel " << r.x);
        CHECK(repeat.alpha(at(u, 0.5f)) == code(51 + 102 * r.repeat));
        CHECK(clamp.alpha(at(u, 0.5f)) == code(51 + 102 * r.clamp));
        CHECK(mirror.alpha(at(u, 0.5f)) == code(51 + 102 * r.mirror));
    }
    // Bilinear across u = 0: repeat blends the last and first texels, mirror the first with itself.
    const ImageTexture repeat_bl(img, {.wrap = WrapMode::repeat});
    const ImageTexture mirror_bl(img, {.wrap = WrapMode::mirror});
    CHECK(repeat_bl.alpha(at(0.0f, 0.5f)) == Approx((code(51) + code(255)) / 2.0f));
    CHECK(mirror_bl.alpha(at(0.0f, 0.5f)) == Approx(code(51)));
    CHECK(mirror_bl.alpha(at(1.0f, 0.5f)) == Approx(code(255)));
    // uv scale and offset apply as for the colour: u' = 3 u + 0.5.
    const ImageTexture scaled(img, {.filter = ImageFilter::nearest, .scale = {3.0f, 1.0f}, .offset = {0.5f, 0.0f}});
    CHECK(scaled.alpha(at(0.1f, 0.5f)) == code(255));
    CHECK(std::isfinite(repeat_bl.alpha(at(1e30f, -1e30f))));
}

TEST_CASE("opaque and transparent regions stay exactly 1 and 0 under bilinear filtering", "[alpha]") {
    for (float fill : {0.0f, 1.0f}) {
        auto img = std::make_shared<Image>(5, 3, RGB(0.3f));
        img->add_alpha(fill);
        const ImageTexture t(img, {.wrap = WrapMode::repeat});
        Rng rng(11);
        int off = 0;
        for (int i = 0; i < 100000; ++i) {
            const float u = (rng.uniform() - 0.5f) * 40.0f, v = (rng.uniform() - 0.5f) * 40.0f;
            off += t.alpha(at(u, v)) == fill ? 0 : 1;
        }
        INFO("fill " << fill);
        CHECK(off == 0);
    }
}

TEST_CASE("textures without alpha report alpha 1 and opacity reads their colour", "[alpha]") {
    const TextureRegistry r = make_texture_registry();
    // An RGB file: no alpha plane.
    write_png(Image(2, 2, RGB(0.5f)), dir / "rgb.png");
    const auto rgb = r.create("image", Params{}.set("filename", (dir / "rgb.png").string()));
    CHECK_FALSE(rgb->has_alpha());
    CHECK(rgb->alpha(at(0.3f, 0.3f)) == 1.0f);
    CHECK(rgb->alpha(at(std::nanf(""), 0.3f)) == 1.0f);
    CHECK(opacity(*rgb, at(0.3f, 0.3f)) == Approx(0.5f).margin(0.003f));  // grey mask: its value
    const auto half = make_constant_texture(RGB(0.5f));
    CHECK_FALSE(half->has_alpha());
    CHECK(half->alpha(at(0.1f, 0.1f)) == 1.0f);
    CHECK(opacity(*half, at(0.1f, 0.1f)) == 0.5f);
    CHECK(opacity(*make_constant_texture(RGB(0.0f, 0.3f, 0.9f)), {}) == Approx(0.4f).epsilon(1e-6));
    const auto checker = r.create("checker", Params{}.set("tiles_u", 1.0));
    CHECK(opacity(*checker, at(0.5f, 0.5f)) == 1.0f);
    CHECK(opacity(*checker, at(1.5f, 0.5f)) == 0.0f);
}

TEST_CASE("an RGBA image is a cut-out: opacity is its alpha and not its colour", "[alpha]") {
    // Saturn's rings: dark colour, holes in alpha. Loaded through the registry as a scene would.
    const TextureRegistry r = make_texture_registry();
    const auto rings =
        r.create("image", Params{}.set("filename", rgba_2x2().string()).set("filter", std::string("nearest")));
    REQUIRE(rings->has_alpha());
    CHECK(opacity(*rings, at(0.25f, 0.75f)) == 0.0f);  // a hole, though the colour is not black
    CHECK(opacity(*rings, at(0.75f, 0.75f)) == 1.0f);  // opaque, though the colour is dark
    CHECK(opacity(*rings, at(0.25f, 0.25f)) == code(102));
    CHECK(scalar(rings->eval(at(0.75f, 0.75f))) < 0.2f);
    // Linear encoding changes the colour, never the alpha.
    const auto linear = r.create("image", Params{}
                                              .set("filename", rgba_2x2().string())
                                              .set("filter", std::string("nearest"))
                                              .set("encoding", std::string("linear")));
    CHECK(linear->alpha(at(0.25f, 0.25f)) == code(102));
    CHECK(linear->eval(at(0.25f, 0.25f)).g > rings->eval(at(0.25f, 0.25f)).g + 0.1f);
}
