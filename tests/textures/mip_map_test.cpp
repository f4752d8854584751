// Image pyramids, textures looked up at a level of detail, baking, and the star field.
#include <rtlab/core/cube_face.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/textures/cube_map.hpp>
#include <rtlab/textures/image_texture.hpp>
#include <rtlab/textures/mip_map.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <catch2/catch.hpp>

#include "texture_lookup.hpp"

#include <cmath>

using namespace rtlab;
using Catch::Matchers::Contains;

using test::at_uv;

TEST_CASE("mip levels: each level the 2 x 2 means of the one before down to 1 x 1", "[mip]") {
    Image img(4, 2);
    img.add_alpha();
    for (int x = 0; x < 4; ++x) {
        img.at(x, 0) = RGB(static_cast<float>(x));
        img.at(x, 1) = RGB(static_cast<float>(x + 4));
        img.alpha_at(x, 0) = x < 2 ? 1.0f : 0.0f;
    }
    const auto levels = mip_levels(std::make_shared<const Image>(img));
    REQUIRE(levels.size() == 3);  // 4x2, 2x1, 1x1
    CHECK(levels[1]->width() == 2);
    CHECK(levels[1]->height() == 1);
    CHECK(levels[1]->at(0, 0).r == 2.5f);  // (0 + 1 + 4 + 5) / 4
    CHECK(levels[1]->at(1, 0).r == 4.5f);
    CHECK(levels[1]->alpha(0, 0) == 1.0f);  // alpha averaged too (the bottom row is opaque)
    CHECK(levels[1]->alpha(1, 0) == 0.5f);
    CHECK(levels[2]->at(0, 0).r == 3.5f);
    // An odd edge repeats its last texel: 3 x 1 -> 1 x 1 is (a + b + a + b) / 4 of the first two columns.
    Image odd(3, 1);
    odd.at(0, 0) = RGB(1.0f), odd.at(1, 0) = RGB(3.0f), odd.at(2, 0) = RGB(100.0f);
    CHECK(downsample(odd).width() == 1);
    CHECK(downsample(odd).at(0, 0).r == 2.0f);
}

TEST_CASE("level blend: two levels around the lod, clamped to the pyramid", "[mip]") {
    const LevelBlend a = level_blend(1.25f, 5);
    CHECK(a.first == 1);
    CHECK(a.second == 2);
    CHECK(a.blend == 0.25f);
    const LevelBlend top = level_blend(9.0f, 5);
    CHECK(top.first == 4);
    CHECK(top.second == 4);
    CHECK(top.blend == 0.0f);
    CHECK(level_blend(-3.0f, 5).first == 0);
    CHECK(level_blend(std::nanf(""), 5).first == 0);
    CHECK(level_blend(std::nanf(""), 5).blend == 0.0f);
}

TEST_CASE("image texture at a lod: level 0 exact, coarser levels the means, fractions blend", "[mip]") {
    // Columns alternate 0 and 1: level 0 shows them, level 1 is 0.5 everywhere.
    Image img(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) img.at(x, y) = RGB(static_cast<float>(x % 2));
    ImageTextureOptions o;
    o.filter = ImageFilter::nearest;
    ImageTexture t(mip_levels(std::make_shared<const Image>(img)), o);
    REQUIRE(t.levels() == 4);
    CHECK(t.eval(at_uv(1.5f / 8.0f, 0.5f)).r == 1.0f);
    t.set_lod(1.0f);
    CHECK(t.eval(at_uv(1.5f / 8.0f, 0.5f)).r == 0.5f);
    t.set_lod(0.5f);
    CHECK(t.eval(at_uv(1.5f / 8.0f, 0.5f)).r == 0.75f);
    CHECK(t.lod() == 0.5f);
    t.set_lod(100.0f);
    CHECK(t.lod() == 3.0f);
    CHECK(t.texels_u() == 8);
}

TEST_CASE("image texture: wrap_v apart from wrap, and intensity scales colour but not alpha", "[mip]") {
    // A column of two rows, 1 on top and 0 below, with alpha 0.5.
    Image img(1, 2);
    img.add_alpha();
    img.at(0, 0) = RGB(1.0f);
    img.alpha_at(0, 0) = img.alpha_at(0, 1) = 0.5f;
    ImageTextureOptions repeat;
    ImageTextureOptions clamp_v;
    clamp_v.wrap_v = WrapMode::clamp;
    clamp_v.intensity = 2.0f;
    const auto image = std::make_shared<const Image>(img);
    // At the very top (v = 1) repeat blends the top row with the bottom one; clamp keeps the top row.
    CHECK(ImageTexture(image, repeat).eval(at_uv(0.5f, 1.0f)).r == 0.5f);
    CHECK(ImageTexture(image, clamp_v).eval(at_uv(0.5f, 1.0f)).r == 2.0f);
    CHECK(ImageTexture(image, clamp_v).alpha(at_uv(0.5f, 1.0f)) == 0.5f);
    // u still repeats: u = 3.5 is u = 0.5.
    CHECK(ImageTexture(image, clamp_v).eval(at_uv(3.5f, 0.75f)).r == 2.0f);
}

TEST_CASE("bake: a solid texture baked on the sphere's uv has no seam at u = 0", "[mip]") {
    // A texture that is the object-space x: at u = 0 and u = 1 the sphere point is the same (-1, 0, 0).
    class PointX final : public Texture {
    public:
        RGB eval(const TextureLookup& q) const override { return RGB(q.point.x); }
    };
    const Image baked = bake_texture(PointX(), 64, 32);
    const float first = baked.at(0, 16).r, last = baked.at(63, 16).r;
    CHECK(first == Approx(last).margin(1e-5));
    CHECK(first < -0.99f);                      // u near 0: -x (rtlab::Sphere's mapping)
    CHECK(baked.at(32, 16).r > 0.99f);          // u = 0.5: +x
    CHECK(std::abs(baked.at(16, 0).r) < 0.1f);  // the top row is near the pole
}

TEST_CASE("the image and cubemap factories: lod builds levels, bake replaces the file", "[mip]") {
    const TextureRegistry r = make_texture_registry();
    Params stars;
    stars.set("resolution", 16.0).set("density", 0.3);
    const auto field = r.create("stars", std::move(stars));
    Params cube;
    cube.set_object<Texture>("bake", field).set("bake_size", 16.0).set("lod", 0.0);
    const auto sky = r.create("cubemap", std::move(cube));
    auto* levels = dynamic_cast<LevelOfDetail*>(sky.get());
    REQUIRE(levels != nullptr);
    CHECK(levels->texels_u() == 16);
    // Baked at the field's own resolution, level 0 holds it exactly at texel centres.
    int stars_seen = 0;
    for (int x = 0; x < 16; ++x) {
        TextureLookup q;
        q.direction = cube_face_direction(CubeFace::pz, (static_cast<float>(x) + 0.5f) / 16.0f, 0.53125f);
        CHECK(sky->eval(q).r == field->eval(q).r);
        stars_seen += field->eval(q).r > 0.0f ? 1 : 0;
    }
    CHECK(stars_seen > 0);
    // The coarsest level is one texel per face, the mean of the face: seen at the face's centre.
    double sum = 0.0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            TextureLookup q;
            q.direction = cube_face_direction(CubeFace::pz, (static_cast<float>(x) + 0.5f) / 16.0f,
                                              (static_cast<float>(y) + 0.5f) / 16.0f);
            sum += field->eval(q).r;
        }
    levels->set_lod(64.0f);
    CHECK(levels->lod() == 4.0f);  // 16, 8, 4, 2, 1
    TextureLookup centre;
    centre.direction = {0.0f, 0.0f, 1.0f};
    CHECK(sky->eval(centre).r == Approx(sum / 256.0).epsilon(1e-5));
    CHECK(sum > 0.0);

    Params image;
    image.set_object<Texture>("bake", field).set("bake_size", Params::List{32.0, 16.0}).set("lod", 1.5);
    const auto baked = r.create("image", std::move(image));
    REQUIRE(dynamic_cast<LevelOfDetail*>(baked.get()) != nullptr);
    CHECK(dynamic_cast<LevelOfDetail*>(baked.get())->lod() == 1.5f);
    Params both;
    both.set("filename", std::string("x.png")).set_object<Texture>("bake", field);
    CHECK_THROWS_WITH(r.create("image", std::move(both)), Contains("not both"));
    Params bad_size;
    bad_size.set_object<Texture>("bake", field).set("bake_size", Params::List{0.0, 16.0});
    CHECK_THROWS_WITH(r.create("image", std::move(bad_size)), Contains("bake_size"));
    Params bad_lod;
    bad_lod.set_object<Texture>("bake", field).set("lod", -1.0);
    CHECK_THROWS_WITH(r.create("image", std::move(bad_lod)), Contains("lod"));
}
