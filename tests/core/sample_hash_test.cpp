#include <rtlab/core/sample_hash.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <set>

using namespace rtlab;

TEST_CASE("a sample's numbers depend only on its key and dimension", "[sample_hash]") {
    const SampleKey key{42, 1000, 7, 3, 1};
    SampleKey same = key;
    for (std::uint32_t d = 0; d < 64; ++d) REQUIRE(sample_uniform(key, d) == sample_uniform(same, d));
}

TEST_CASE("changing any field or the dimension gives another number", "[sample_hash]") {
    const SampleKey base{42, 1000, 7, 3, 1};
    std::set<std::uint64_t> seen;
    seen.insert(sample_hash(base, 0));
    SampleKey k = base;
    k.seed += 1;
    seen.insert(sample_hash(k, 0));
    k = base;
    k.x += 1;
    seen.insert(sample_hash(k, 0));
    k = base;
    k.y += 1;
    seen.insert(sample_hash(k, 0));
    k = base;
    k.sample += 1;
    seen.insert(sample_hash(k, 0));
    k = base;
    k.bounce += 1;
    seen.insert(sample_hash(k, 0));
    seen.insert(sample_hash(base, 1));
    // x and y swapped must not collide either (a symmetric combination would).
    k = base;
    k.x = base.y;
    k.y = base.x;
    seen.insert(sample_hash(k, 0));
    CHECK(seen.size() == 8);
}

TEST_CASE("uniforms over a lattice of neighbouring keys are uniform and uncorrelated", "[sample_hash]") {
    // 256 x 256 neighbouring lattice positions: the case where a weak hash shows structure.
    constexpr int kBins = 16;
    std::array<int, kBins> bins{};
    std::array<int, kBins * kBins> pairs{};
    double sum = 0.0;
    int n = 0;
    for (std::uint32_t y = 0; y < 256; ++y)
        for (std::uint32_t x = 0; x < 256; ++x) {
            const SampleKey key{5, x, y, 0, 0};
            const Vec2 u = sample_uniform2(key, 0);
            REQUIRE(u.x >= 0.0f);
            REQUIRE(u.x < 1.0f);
            ++bins[static_cast<int>(u.x * kBins)];
            ++pairs[static_cast<int>(u.x * kBins) * kBins + static_cast<int>(u.y * kBins)];
            sum += u.x;
            ++n;
        }
    CHECK(std::abs(sum / n - 0.5) < 0.005);
    // Chi-square with 15 and 255 degrees of freedom; the limits are far beyond the 0.1% quantiles
    // (37.7 and 330), so a correct hash never fails while a structured one fails by orders of magnitude.
    auto chi2 = [](const auto& counts, double expected) {
        double c = 0.0;
        for (int v : counts) c += (v - expected) * (v - expected) / expected;
        return c;
    };
    CHECK(chi2(bins, n / double(kBins)) < 40.0);
    CHECK(chi2(pairs, n / double(kBins * kBins)) < 340.0);
}
