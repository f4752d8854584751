#include <rtlab/core/rng.hpp>

#include <catch2/catch.hpp>

#include <set>
#include <vector>

using namespace rtlab;

TEST_CASE("same seed and pixel give the same sequence", "[rng]") {
    Rng a = Rng::for_pixel(1234, 17, 99);
    Rng b = Rng::for_pixel(1234, 17, 99);
    for (int i = 0; i < 1000; ++i) REQUIRE(a.next_u32() == b.next_u32());
}

TEST_CASE("different pixels and seeds give different sequences", "[rng]") {
    std::set<std::vector<std::uint32_t>> seen;
    for (std::uint64_t seed : {1u, 2u})
        for (std::uint32_t y = 0; y < 8; ++y)
            for (std::uint32_t x = 0; x < 8; ++x) {
                Rng r = Rng::for_pixel(seed, x, y);
                std::vector<std::uint32_t> seq;
                for (int i = 0; i < 4; ++i) seq.push_back(r.next_u32());
                seen.insert(seq);
            }
    CHECK(seen.size() == 128);
}

TEST_CASE("uniform floats lie in the half-open unit interval and are roughly uniform", "[rng]") {
    Rng r(7);
    int buckets[10] = {};
    constexpr int n = 100000;
    for (int i = 0; i < n; ++i) {
        const float u = r.uniform();
        REQUIRE(u >= 0.0f);
        REQUIRE(u < 1.0f);
        ++buckets[static_cast<int>(u * 10)];
    }
    for (int b : buckets) CHECK(std::abs(b - n / 10) < 600);  // > 6 sigma would be a broken generator
    for (int i = 0; i < 1000; ++i) REQUIRE(r.uniform_u32(3) < 3);
}

TEST_CASE("advance skips ahead exactly", "[rng]") {
    Rng a(5, 3), b(5, 3);
    for (int i = 0; i < 10; ++i) a.next_u32();
    b.advance(10);
    CHECK(a.next_u32() == b.next_u32());
}
