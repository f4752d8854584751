#include <rtlab/core/error.hpp>
#include <rtlab/render/pixel_sampler.hpp>

#include <catch2/catch.hpp>

#include <set>

using namespace rtlab;

TEST_CASE("jittered samples fill every stratum exactly once", "[sampler]") {
    Rng rng(9);
    for (int spp : {1, 4, 9, 16, 10}) {
        const auto s = pixel_samples(PixelPattern::jittered, spp, rng);
        const int n = static_cast<int>(std::ceil(std::sqrt(spp)));
        REQUIRE(s.size() == static_cast<std::size_t>(n * n));
        std::set<std::pair<int, int>> cells;
        for (const Vec2& p : s) {
            REQUIRE(p.x >= 0.0f);
            REQUIRE(p.x < 1.0f);
            REQUIRE(p.y >= 0.0f);
            REQUIRE(p.y < 1.0f);
            cells.insert({static_cast<int>(p.x * n), static_cast<int>(p.y * n)});
        }
        CHECK(cells.size() == s.size());
    }
}

TEST_CASE("grid samples sit at cell centres and none is the pixel centre", "[sampler]") {
    Rng rng(1);
    const auto g = pixel_samples(PixelPattern::grid, 4, rng);
    REQUIRE(g.size() == 4);
    CHECK(g[0] == Vec2(0.25f, 0.25f));
    CHECK(g[3] == Vec2(0.75f, 0.75f));
    CHECK(pixel_samples(PixelPattern::none, 16, rng) == std::vector<Vec2>{Vec2(0.5f)});
    CHECK(pixel_samples(PixelPattern::random, 7, rng).size() == 7);
}

TEST_CASE("pattern names and sample counts are checked", "[sampler]") {
    using Catch::Matchers::Contains;
    CHECK(parse_pixel_pattern("jittered") == PixelPattern::jittered);
    CHECK_THROWS_WITH(parse_pixel_pattern("adaptiv"), Contains("none, grid, random, jittered"));
    Rng rng(1);
    CHECK_THROWS_AS(pixel_samples(PixelPattern::grid, 0, rng), Error);
}
