#include <rtlab/core/asset_manifest.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/core/srgb.hpp>
#include <rtlab/textures/image_texture.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"
#include "skip.hpp"

#include <cmath>
#include <fstream>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
const auto dir = test::scratch_dir("textures_image");

// A 2x2 image written as PFM (exact floats): a b on the top row, c d below, in the red channel.
std::filesystem::path two_by_two() {
    Image img(2, 2);
    img.at(0, 0) = RGB(1.0f, 0.0f, 0.0f);
    img.at(1, 0) = RGB(10.0f, 0.0f, 0.0f);
    img.at(0, 1) = RGB(100.0f, 0.0f, 0.0f);
    img.at(1, 1) = RGB(1000.0f, 0.0f, 0.0f);
    const auto path = dir / "two_by_two.pfm";
    write_image(img, path);
    return path;
}

// A 3x1 row p0 p1 p2 = 1, 2, 3.
std::shared_ptr<const Image> row3() {
    auto img = std::make_shared<Image>(3, 1);
    for (int x = 0; x < 3; ++x) img->at(x, 0) = RGB(static_cast<float>(x + 1));
    return img;
}

float red(const Texture& t, float u, float v) { return t.eval(TextureLookup{{u, v}, {}, {}}).r; }
}  // namespace

TEST_CASE("bilinear weights on a 2x2 image match the hand-computed blend", "[image]") {
    const auto t = ImageTexture::load(two_by_two(), {.wrap = WrapMode::clamp});
    // Texel centres: u = 0.25 (column 0), 0.75 (column 1); v = 0.75 (row 0, top), 0.25 (row 1).
    CHECK(red(*t, 0.25f, 0.75f) == 1.0f);
    CHECK(red(*t, 0.75f, 0.75f) == 10.0f);
    CHECK(red(*t, 0.25f, 0.25f) == 100.0f);
    CHECK(red(*t, 0.75f, 0.25f) == 1000.0f);
    // Centre: the mean of all four.
    CHECK(red(*t, 0.5f, 0.5f) == Approx(277.75f).epsilon(1e-6));
    // (0.375, 0.75): x = 0.25 along the top row: 0.75 a + 0.25 b.
    CHECK(red(*t, 0.375f, 0.75f) == Approx(0.75f * 1 + 0.25f * 10).epsilon(1e-6));
    // (0.4, 0.6): x = 0.4 * 2 - 0.5 = 0.3, y = (1 - 0.6) * 2 - 0.5 = 0.3:
    // 0.49 a + 0.21 b + 0.21 c + 0.09 d = 0.49 + 2.1 + 21 + 90 = 113.59.
    CHECK(red(*t, 0.4f, 0.6f) == Approx(113.59f).epsilon(1e-5));
    // Clamp: beyond the texel centres the edge texels extend.
    CHECK(red(*t, 0.0f, 1.0f) == 1.0f);
    CHECK(red(*t, -3.0f, 0.75f) == 1.0f);
    CHECK(red(*t, 0.75f, -2.0f) == 1000.0f);
}

TEST_CASE("wrap modes repeat clamp and mirror pick the texels beyond the edges", "[image]") {
    const auto img = row3();
    const ImageTexture repeat(img, {.wrap = WrapMode::repeat, .filter = ImageFilter::nearest});
    const ImageTexture clamp(img, {.wrap = WrapMode::clamp, .filter = ImageFilter::nearest});
    const ImageTexture mirror(img, {.wrap = WrapMode::mirror, .filter = ImageFilter::nearest});
    // u at the centre of texel x: (x + 0.5) / 3. Beyond the image, texel x reads
    //   repeat: x mod 3; clamp: clamp(x, 0, 2); mirror: period 6, 3 4 5 -> 2 1 0, -1 -2 -3 -> 0 1 2.
    struct Row {
        int x;
        float repeat, clamp, mirror;
    };
    for (const Row& r : {Row{-1, 3, 1, 1}, Row{-2, 2, 1, 2}, Row{-3, 1, 1, 3}, Row{-4, 3, 1, 3}, Row{3, 1, 3, 3},
                         Row{4, 2, 3, 2}, Row{5, 3, 3, 1}, Row{6, 1, 3, 1}, Row{1, 2, 2, 2}, Row{-7, 3, 1, 1}}) {
        const float u = (static_cast<float>(r.x) + 0.5f) / 3.0f;
        INFO("texel " << r.x);
        CHECK(red(repeat, u, 0.5f) == r.repeat);
        CHECK(red(clamp, u, 0.5f) == r.clamp);
        CHECK(red(mirror, u, 0.5f) == r.mirror);
    }
    // Bilinear across the u = 0 edge (x = -0.5 between texels -1 and 0): repeat blends p2 and p0.
    const ImageTexture repeat_bl(img, {.wrap = WrapMode::repeat});
    const ImageTexture mirror_bl(img, {.wrap = WrapMode::mirror});
    CHECK(red(repeat_bl, 0.0f, 0.5f) == Approx(2.0f));  // (3 + 1) / 2
    CHECK(red(repeat_bl, 1.0f, 0.5f) == Approx(2.0f));  // the same place one period on
    CHECK(red(mirror_bl, 0.0f, 0.5f) == Approx(1.0f));  // mirrored: p0 beside p0
    CHECK(red(mirror_bl, 1.0f, 0.5f) == Approx(3.0f));
    // Repeat is periodic far out, and huge or non-finite uv do not crash.
    CHECK(red(repeat_bl, 1000.25f, 0.5f) == Approx(red(repeat_bl, 0.25f, 0.5f)).epsilon(1e-4));
    CHECK(std::isfinite(red(repeat_bl, 1e30f, -1e30f)));
    CHECK(std::isfinite(red(mirror_bl, -1e30f, 1e30f)));
    CHECK(red(repeat_bl, std::nanf(""), 0.5f) == 0.0f);
    CHECK(parse_wrap_mode("mirror") == WrapMode::mirror);
    CHECK_THROWS_WITH(parse_wrap_mode("wrap"), Contains("unknown wrap mode 'wrap'"));
}

TEST_CASE("uv scale and offset apply before the lookup", "[image]") {
    const ImageTexture plain(row3(), {.filter = ImageFilter::nearest});
    const ImageTexture scaled(row3(), {.filter = ImageFilter::nearest, .scale = {3.0f, 1.0f}, .offset = {0.5f, 0.0f}});
    // u' = 3 u + 0.5: u = 0.1 -> 0.8 (texel 2); u = 0 -> 0.5 (texel 1).
    CHECK(red(scaled, 0.1f, 0.5f) == red(plain, 0.8f, 0.5f));
    CHECK(red(scaled, 0.1f, 0.5f) == 3.0f);
    CHECK(red(scaled, 0.0f, 0.5f) == 2.0f);
    // Through the registry: scale and offset as lists or single numbers.
    const TextureRegistry r = make_texture_registry();
    const auto t = r.create("image", Params{}
                                         .set("filename", two_by_two().string())
                                         .set("filter", std::string("nearest"))
                                         .set("scale", 0.5)
                                         .set("offset", Params::List{0.5, 0.0}));
    CHECK(red(*t, 0.1f, 0.1f) == 1000.0f);  // u' = 0.55 (column 1), v' = 0.05 (bottom row)
}

TEST_CASE("8-bit images are decoded from sRGB unless told they are linear", "[image]") {
    const auto path = dir / "grey.png";
    write_image(Image(4, 4, RGB(0.2f)), path);  // stored as the sRGB code of 0.2
    const TextureRegistry r = make_texture_registry();
    const auto srgb = r.create("image", Params{}.set("filename", path.string()));
    const auto linear =
        r.create("image", Params{}.set("filename", path.string()).set("encoding", std::string("linear")));
    CHECK(red(*srgb, 0.3f, 0.3f) == Approx(0.2f).margin(0.003f));
    CHECK(red(*linear, 0.3f, 0.3f) == Approx(srgb_encode(0.2f)).margin(0.003f));  // about 0.484
}

TEST_CASE("missing or corrupt image files are errors naming the file", "[image]") {
    const TextureRegistry r = make_texture_registry();
    const auto missing = dir / "no_such_image.png";
    CHECK_THROWS_WITH(r.create("image", Params{}.set("filename", missing.string())),
                      Contains("texture 'image'") && Contains("no_such_image.png"));
    const auto corrupt = dir / "corrupt.png";
    std::ofstream(corrupt, std::ios::binary) << "\x89PNG\r\n\x1a\n this is not a png";
    CHECK_THROWS_WITH(r.create("image", Params{}.set("filename", corrupt.string())),
                      Contains("texture 'image'") && Contains("corrupt.png"));
    const auto empty = dir / "empty.jpg";
    std::ofstream(empty, std::ios::binary).flush();
    CHECK_THROWS_WITH(ImageTexture::load(empty), Contains("empty.jpg"));
    CHECK_THROWS_AS(ImageTexture(std::make_shared<Image>()), Error);
}

namespace {

// Mean absolute difference of columns x0 and x1 over the image's rows and channels.
double column_difference(const Image& image, int x0, int x1) {
    double sum = 0.0;
    for (int y = 0; y < image.height(); ++y)
        for (int c = 0; c < 3; ++c) sum += std::abs(image.at(x0, y)[c] - image.at(x1, y)[c]);
    return sum / (3.0 * image.height());
}

// A planet map's u = 0 and u = 1 are the same meridian: with repeat wrap the two sample alike, and the map's
// first and last columns are neighbours on the sphere, about as close as two neighbouring columns (within 3
// times, plus 0.01 for the banded planets whose columns hardly differ: JPEG and the maps' own joins), and far
// closer than two columns half a turn apart (Earth: 0.026 at the seam, 0.013 next door, 0.16 half a turn away).
void check_seamless(const std::filesystem::path& file) {
    INFO(file.string());
    const auto map = ImageTexture::load(file);
    const Image& image = map->image();
    CHECK(image.width() == 2 * image.height());
    for (float v : {0.1f, 0.3f, 0.5f, 0.7f, 0.9f}) {
        const RGB a = map->sample({0.0f, v}), b = map->sample({1.0f, v});
        CHECK(a.r == Approx(b.r).margin(1e-6));
        CHECK(a.is_finite());
        CHECK(a.max_component() <= 1.0f);
    }
    const int last = image.width() - 1;
    const double seam = column_difference(image, 0, last), neighbours = column_difference(image, 0, 1);
    CHECK(seam < 3.0 * neighbours + 0.01);
    CHECK(seam < 0.5 * column_difference(image, 0, image.width() / 2) + 0.01);
}

}  // namespace

TEST_CASE("a real planet map loads and wraps seamlessly in u", "[image]") {
    const auto shared = test::shared_dir();
    if (!shared || !std::filesystem::exists(*shared / "textures" / "earth.jpg"))
        return test::skip(test::needs_shared("textures/earth.jpg"));
    const auto earth = ImageTexture::load(*shared / "textures" / "earth.jpg");
    CHECK(earth->image().width() == 2048);
    CHECK(earth->image().height() == 1024);
    check_seamless(*shared / "textures" / "earth.jpg");
}

TEST_CASE("the package planet maps wrap seamlessly in u", "[image]") {
    int checked = 0;
    for (const AssetEntry& e : asset_manifest()) {
        // The planet maps the solar system uses: every package image but the ring strip and the Moon's, whose
        // first and last columns differ as much as any two (0.23): a seam, in a map no course scene uses.
        if (!e.from_package() || e.name.rfind("textures/", 0) != 0) continue;
        if (e.name == "textures/saturn_ring.png" || e.name == "textures/moon.jpg") continue;
        if (!std::filesystem::is_regular_file(e.file)) continue;
        check_seamless(e.file);
        ++checked;
    }
    if (checked == 0) return test::skip("openuniverse-common is not installed (scripts/setup.sh)");
}
