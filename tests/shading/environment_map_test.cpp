// Environment maps on synthetic images: sampled directions against pdf_li (a chi-square on the map's own cells, a
// map with a spot 30,000 times brighter than its sky, a map with zero bands, a cube map), the density's integral,
// the orientation the header documents (one bright texel lights the side it should, for several rotations), and
// what a bad map is told. The studio maps of blender-data are checked the same way in tests/render.
#include <rtlab/core/error.hpp>
#include <rtlab/shading/environment_map.hpp>
#include <rtlab/shading/light_set.hpp>

#include <catch2/catch.hpp>

#include "environment_checks.hpp"

#include <cmath>

using namespace rtlab;
using test::equirect_direction;

namespace {

// A sky of smooth colour, brighter above the horizon, with one texel 30,000 times brighter (a sun).
Image spot_map() {
    Image img(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) img.at(x, y) = RGB(0.2f + 0.8f * (y < 16), 0.3f + 0.01f * x, 0.5f + 0.02f * y);
    img.at(40, 9) = RGB(30000.0f, 28000.0f, 25000.0f);
    return img;
}

// Zero where a lookup blends only zeros: the bottom rows, a band of columns, a black hole in the sky.
Image banded_map() {
    Image img(48, 24);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 48; ++x) {
            const bool dark = y >= 20 || (x >= 10 && x < 16) || (x >= 30 && x < 34 && y >= 4 && y < 9);
            img.at(x, y) = dark ? RGB(0.0f) : RGB(1.0f + std::sin(0.3f * x), 0.5f, 2.0f - 0.05f * y);
        }
    return img;
}

std::array<Image, 6> cube_faces() {
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) {
        faces[f] = Image(8, 8);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) faces[f].at(x, y) = RGB(0.1f * (f + 1) + 0.02f * x * y, 0.4f, 0.3f);
    }
    faces[4].at(7, 2) = RGB(5000.0f);  // by the edge of +z towards +x
    faces[3].at(0, 0) = RGB(0.0f);     // a black corner texel
    return faces;
}

void check_sampling(const EnvironmentMap& map, const char* name, std::uint64_t seed, int bu, int bv, double level) {
    Rng rng(seed);
    const int n = 300000 / test::kSampleScale;
    const test::EnvironmentSamplingResult r = test::check_environment_sampling(map, rng, n, bu, bv);
    INFO(name << ": chi2 " << r.chi2.statistic << " dof " << r.chi2.dof << " p " << r.chi2.p_value << " ("
              << r.chi2.failure << r.chi2.worst << "), pdf integral " << r.pdf_integral << ", pdf mismatches "
              << r.pdf_mismatches << ", lost " << r.lost);
    CHECK(r.chi2.failure.empty());
    CHECK(r.chi2.p_value > level);
    CHECK(r.pdf_integral == Approx(1.0).epsilon(1e-3));
    CHECK(r.lost == 0);
    // Directions that land on a cell's edge may read the neighbouring cell's density.
    CHECK(r.pdf_mismatches <= n / 1000);
    CHECK(r.radiance_mismatches <= n / 1000);
}

}  // namespace

TEST_CASE("environment maps sample directions by their pdf_li", "[environment]") {
    const double level = test::sidak_level(1e-3, 5);
    // The spot in fine bins (its 4 x 4 cells apart), and in coarse ones where the sky's bins expect enough draws.
    check_sampling(EnvironmentMap(spot_map(), {.rotation_degrees = 90.0f}), "spot, turned 90 degrees", 1, 2, 2, level);
    check_sampling(EnvironmentMap(spot_map(), {.rotation_degrees = 90.0f}), "spot, coarse bins", 5, 8, 8, level);
    check_sampling(EnvironmentMap(banded_map(), {.rotation_degrees = -33.0f}), "zero bands, turned -33 degrees", 2, 2,
                   2, level);
    check_sampling(EnvironmentMap(banded_map()), "zero bands", 3, 1, 1, level);
    check_sampling(EnvironmentMap(cube_faces(), {.rotation_degrees = 45.0f}), "cube, turned 45 degrees", 4, 2, 2,
                   level);
}

TEST_CASE("an environment map's density is positive wherever its radiance is, and zero cells are never drawn",
          "[environment]") {
    const EnvironmentMap map(banded_map());
    Rng rng(9);
    for (int k = 0; k < 20000; ++k) {
        // Anywhere the map gives light, light sampling can find it...
        const Vec3 w = glm::normalize(Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f));
        if (map.radiance(w).luminance() > 0.0f) REQUIRE(map.pdf_li(Point3(0.0f), w, Point3(0.0f), w) > 0.0f);
        // ...and what it draws gives light (none falls among the zero texels).
        const auto s = map.sample_li(Point3(0.0f), rng.uniform2());
        REQUIRE(s);
        REQUIRE(s->radiance.luminance() > 0.0f);
    }
}

TEST_CASE("one bright texel lights the side the documented orientation says", "[environment]") {
    // Texel (4, 3) of 16 x 8: u = 0.28, just west of -z (u = 0.25), a little above the horizon. Turned by the
    // right-hand rule about +y: 0 -> towards -z, 90 -> -x, 180 -> +z, -90 -> +x.
    Image img(16, 8);
    img.at(4, 3) = RGB(1.0f, 2.0f, 3.0f);
    const double u = 4.5 / 16, v = 3.5 / 8;
    const std::pair<float, Vec3> cases[] = {
        {0.0f, {0, 0, -1}}, {90.0f, {-1, 0, 0}}, {180.0f, {0, 0, 1}}, {-90.0f, {1, 0, 0}}, {270.0f, {1, 0, 0}}};
    for (const auto& [degrees, side] : cases) {
        INFO("rotation " << degrees);
        const EnvironmentMap map(img, {.rotation_degrees = degrees});
        // At the texel's centre the lookup is the texel; half a texel away, half of it.
        const Vec3 centre(equirect_direction(u, v, degrees));
        CHECK(map.radiance(centre).b == Approx(3.0f).epsilon(1e-3));
        CHECK(map.radiance(Vec3(equirect_direction(u + 0.5 / 16, v, degrees))).b == Approx(1.5f).epsilon(1e-2));
        CHECK(map.radiance(Vec3(equirect_direction(u + 0.5, v, degrees))).b == 0.0f);
        CHECK(glm::dot(centre, side) > 0.95f);
        // Light sampling finds it there...
        Rng rng(1);
        Vec3 mean(0.0f);
        for (int k = 0; k < 1000; ++k) mean += map.sample_li(Point3(0.0f), rng.uniform2())->wi;
        CHECK(glm::dot(glm::normalize(mean), side) > 0.95f);
        // ...and of four walls facing the horizon's quarters, the one facing it is lit most.
        double best = -1.0;
        Vec3 lit(0.0f);
        for (const Vec3& n : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
            const double e = test::reflected_by_quadrature(map, glm::dvec3(n));
            if (e > best) best = e, lit = n;
        }
        CHECK(lit == side);
    }
}

TEST_CASE("a cube map's radiance is the cube map texture's and its orientation is core's", "[environment]") {
    std::array<Image, 6> faces = cube_faces();
    const CubeMapTexture texture(faces);
    const EnvironmentMap map(faces);
    const EnvironmentMap turned(faces, {.rotation_degrees = 90.0f});
    Rng rng(3);
    for (int k = 0; k < 1000; ++k) {
        const Vec3 w = glm::normalize(Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f));
        CHECK(map.radiance(w).r == Approx(texture.sample(w).r).epsilon(1e-5));
        // Turned 90 degrees: what was at local +x is seen at world -z.
        const Vec3 world(w.z, w.y, -w.x);
        CHECK(turned.radiance(world).r == Approx(texture.sample(w).r).epsilon(1e-4));
    }
}

TEST_CASE("an environment map's power is its radiance integral times pi r^2", "[environment]") {
    Image img(32, 16, RGB(2.0f, 1.0f, 0.5f));
    const EnvironmentMap map(img, {.intensity = RGB(3.0f)});
    CHECK(map.radiance_integral().r == Approx(4.0 * kPi * 6.0).epsilon(1e-4));
    CHECK(map.power().g == Approx(4.0 * kPi * 3.0 * kPi).epsilon(1e-4));
    const auto wide = map.for_scene_radius(10.0f);
    CHECK(wide->power().g == Approx(100.0 * map.power().g).epsilon(1e-5));
    CHECK(wide->radiance(Vec3(0, 1, 0)).r == Approx(6.0f));
    std::array<Image, 6> flat;
    for (Image& face : flat) face = Image(4, 4, RGB(0.4f));
    CHECK(EnvironmentMap(flat).radiance_integral().g == Approx(4.0 * kPi * 0.4).epsilon(1e-3));
}

TEST_CASE("a bad environment map is an error saying what is wrong", "[environment]") {
    using Catch::Contains;
    CHECK_THROWS_WITH(EnvironmentMap(Image()), Contains("empty"));
    Image nan(4, 2, RGB(1.0f));
    nan.at(3, 1).g = std::nanf("");
    CHECK_THROWS_WITH(EnvironmentMap(nan), Contains("texel (3, 1) is not finite"));
    CHECK_THROWS_WITH(EnvironmentMap(Image(4, 2), {.intensity = RGB(-1.0f)}), Contains("intensity"));
    std::array<Image, 6> faces = cube_faces();
    faces[2] = Image(4, 4);
    CHECK_THROWS_WITH(EnvironmentMap(faces), Contains("'py' is 4x4"));
    // Negative texels (ringing from resampling) read as 0.
    Image negative(4, 2, RGB(-1.0f));
    CHECK(EnvironmentMap(negative).radiance(Vec3(0, 1, 0)) == RGB(0.0f));
    LightSet set;
    set.set_environment(std::make_shared<UniformEnvironment>(RGB(1.0f), 1.0f));
    CHECK_THROWS_AS(set.set_environment(std::make_shared<EnvironmentMap>(Image(2, 1, RGB(1.0f)))), Error);
}
