#include <rtlab/core/error.hpp>
#include <rtlab/render/pixel_sampler.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <set>

using namespace rtlab;

TEST_CASE("jittered samples fill every stratum exactly once", "[sampler]") {
    for (int spp : {1, 4, 9, 16, 10}) {
        const auto s = pixel_samples(PixelPattern::jittered, spp, SampleKey{9, 3, 4, 0, 0});
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
    const SampleKey key{1, 0, 0, 0, 0};
    const auto g = pixel_samples(PixelPattern::grid, 4, key);
    REQUIRE(g.size() == 4);
    CHECK(g[0] == Vec2(0.25f, 0.25f));
    CHECK(g[1] == Vec2(0.75f, 0.25f));
    CHECK(g[3] == Vec2(0.75f, 0.75f));
    CHECK(pixel_samples(PixelPattern::none, 16, key) == std::vector<Vec2>{Vec2(0.5f)});
    CHECK(pixel_samples(PixelPattern::random, 7, key).size() == 7);
}

TEST_CASE("random samples are a pure function of seed pixel and index", "[sampler]") {
    const SampleKey a{5, 10, 20, 0, 0};
    CHECK(pixel_samples(PixelPattern::random, 8, a) == pixel_samples(PixelPattern::random, 8, a));
    for (SampleKey b : {SampleKey{6, 10, 20, 0, 0}, SampleKey{5, 11, 20, 0, 0}, SampleKey{5, 10, 21, 0, 0}}) {
        const auto sa = pixel_samples(PixelPattern::random, 8, a);
        const auto sb = pixel_samples(PixelPattern::random, 8, b);
        int same = 0;
        for (std::size_t i = 0; i < sa.size(); ++i) same += sa[i] == sb[i];
        CHECK(same == 0);
    }
    // The sample field of the key passed in is ignored: the index decides.
    CHECK(pattern_sample(PixelPattern::random, 8, 3, SampleKey{5, 10, 20, 77, 0}) ==
          pixel_samples(PixelPattern::random, 8, a)[3]);
}

TEST_CASE("pattern names and sample counts are checked", "[sampler]") {
    using Catch::Matchers::Contains;
    CHECK(parse_pixel_pattern("jittered") == PixelPattern::jittered);
    CHECK(parse_pixel_pattern("adaptive") == PixelPattern::adaptive);
    for (auto p : {PixelPattern::none, PixelPattern::grid, PixelPattern::random, PixelPattern::jittered,
                   PixelPattern::adaptive, PixelPattern::sobol})
        CHECK(parse_pixel_pattern(pixel_pattern_name(p)) == p);
    CHECK_THROWS_WITH(parse_pixel_pattern("adaptiv"), Contains("none, grid, random, jittered, adaptive, sobol"));
    CHECK(pattern_sample_count(PixelPattern::sobol, 7) == 7);
    CHECK_THROWS_AS(pattern_sample_count(PixelPattern::grid, 0), Error);
    CHECK_THROWS_AS(pattern_sample_count(PixelPattern::random, kMaxSamplesPerPixel + 1), Error);
    CHECK_THROWS_WITH(pattern_sample_count(PixelPattern::adaptive, 4), Contains("adaptive"));
    CHECK(pattern_sample_count(PixelPattern::grid, 10) == 16);
    CHECK(pattern_sample_count(PixelPattern::jittered, kMaxSamplesPerPixel) == kMaxSamplesPerPixel);
}

TEST_CASE("display difference is POV-Ray's summed absolute difference of clamped colours", "[sampler]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    CHECK(display_difference(RGB(0.1f, 0.2f, 0.3f), RGB(0.2f, 0.0f, 0.3f)) == Approx(0.3f));
    // Clamped to [0, 1] first: HDR values above 1 and negatives do not count beyond the display range.
    CHECK(display_difference(RGB(5.0f, -3.0f, 1.0f), RGB(1.0f, 0.0f, 2.0f)) == 0.0f);
    CHECK(display_difference(RGB(inf, 0, 0), RGB(0, 0, 0)) == 1.0f);
    CHECK(display_difference(RGB(-inf, 0, 0), RGB(0, 0, 0)) == 0.0f);
    CHECK(display_difference(RGB(0, 0, 0), RGB(1, 1, 1)) == 3.0f);
    // NaN differs by the maximum per component, from anything including NaN.
    CHECK(display_difference(RGB(nan, 0, 0), RGB(0, 0, 0)) == 1.0f);
    CHECK(display_difference(RGB(nan, nan, nan), RGB(nan, nan, nan)) == 3.0f);
    CHECK(display_difference(RGB(0.5f, nan, 0.5f), RGB(0.5f, 0.5f, 0.5f)) == 1.0f);
}
