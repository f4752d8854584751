#include <rtlab/core/low_discrepancy.hpp>
#include <rtlab/core/sample_stream.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

using namespace rtlab;

namespace {

/// The first n points of pair `pair` of pixel (x, y) under `seed`.
std::vector<Vec2> pair_points(std::uint64_t seed, std::uint32_t x, std::uint32_t y, std::uint32_t pair, int n,
                              SampleSequence sequence = SampleSequence::sobol) {
    std::vector<Vec2> out;
    for (int i = 0; i < n; ++i)
        out.push_back(SampleStream(sequence, SampleKey{seed, x, y, static_cast<std::uint32_t>(i), 0}).get2d(pair));
    return out;
}

/// Whether points [begin, begin + 2^k) put exactly one point in every elementary interval of area 2^-k:
/// every split of k into 2^a columns and 2^(k-a) rows.
bool is_02_net(const std::vector<Vec2>& p, std::size_t begin, int k) {
    const std::size_t n = std::size_t{1} << k;
    for (int a = 0; a <= k; ++a) {
        std::vector<int> cells(n, 0);
        for (std::size_t i = begin; i < begin + n; ++i) {
            const auto cx = static_cast<std::size_t>(std::floor(p[i].x * static_cast<float>(1 << a)));
            const auto cy = static_cast<std::size_t>(std::floor(p[i].y * static_cast<float>(1 << (k - a))));
            if (++cells[(cy << a) | cx] > 1) return false;
        }
    }
    return true;
}

double correlation(const std::vector<float>& a, const std::vector<float>& b) {
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
    ma /= static_cast<double>(a.size());
    mb /= static_cast<double>(b.size());
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
}

}  // namespace

TEST_CASE("sobol dimension 0 is van der Corput and dimension 1 is Pascal's triangle mod 2", "[low_discrepancy]") {
    for (std::size_t j = 0; j < 32; ++j) {
        CHECK(kSobolDirections[0][j] == (1u << (31 - j)));
        // Lucas: C(j, r) is odd exactly when r's bits are a subset of j's; output digit r is bit 31 - r.
        std::uint32_t pascal = 0;
        for (std::uint32_t r = 0; r <= j; ++r)
            if ((r & j) == r) pascal |= 1u << (31 - r);
        CHECK(kSobolDirections[1][j] == pascal);
    }
    CHECK(sobol_sample(0, 1) == 0u);
    CHECK(sobol_sample(1, 0) == 0x80000000u);
    CHECK(sobol_sample(3, 1) == (kSobolDirections[1][0] ^ kSobolDirections[1][1]));
    // The byte tables give the XOR of the direction numbers of the set bits, for any index.
    std::uint64_t state = 5;
    for (int t = 0; t < 1000; ++t) {
        const auto index = static_cast<std::uint32_t>((state = mix_seed(state + 0x9e3779b97f4a7c15ULL)) >> 7);
        for (int d = 0; d < kSobolDimensions; ++d) {
            std::uint32_t x = 0;
            for (std::size_t b = 0; b < 32; ++b)
                if ((index >> b) & 1u) x ^= kSobolDirections[static_cast<std::size_t>(d)][b];
            REQUIRE(sobol_sample(index, d) == x);
        }
    }
}

TEST_CASE("direction numbers from any primitive polynomial stratify their own dimension", "[low_discrepancy]") {
    // x^2 + x + 1 (m = 1, 3) and x^3 + x + 1 (m = 1, 3, 1): a valid Sobol dimension puts the first 2^k points in
    // the 2^k intervals of length 2^-k, one each, which needs every leading k x k block of its matrix invertible.
    const auto d2 = sobol_direction_numbers<2>(1, {1, 3});
    const auto d3 = sobol_direction_numbers<3>(0b01, {1, 3, 1});  // a_1 = 0 (x^2), a_2 = 1 (x)
    // By hand: m_3 = 2 m_2 ^ 4 m_1 ^ m_1 = 6 ^ 4 ^ 1 = 3 and m_4 = 2 m_3 ^ 4 m_2 ^ m_2 = 6 ^ 12 ^ 3 = 9 for the
    // first; m_4 = 4 a_2 m_2 ^ 8 m_1 ^ m_1 = 12 ^ 8 ^ 1 = 5 for the second.
    CHECK(d2[2] == (3u << 29));
    CHECK(d2[3] == (9u << 28));
    CHECK(d3[3] == (5u << 28));
    for (const auto& v : {d2, d3}) {
        for (int k = 0; k <= 12; ++k) {
            std::set<std::uint32_t> cells;
            for (std::uint32_t i = 0; i < (1u << k); ++i) {
                std::uint32_t x = 0;
                for (std::uint32_t b = 0; b < 32; ++b)
                    if ((i >> b) & 1u) x ^= v[b];
                cells.insert(k == 0 ? 0u : x >> (32 - k));
            }
            CHECK(cells.size() == (std::size_t{1} << k));
        }
    }
}

TEST_CASE("owen scrambling keeps shared leading digits and is uniform over seeds", "[low_discrepancy]") {
    // Two values agreeing in their top j bits still agree there after scrambling, and differ in bit j if they
    // did: a nested scramble flips each digit by a function of the digits above it.
    std::uint64_t state = 1;
    auto next = [&] { return static_cast<std::uint32_t>((state = mix_seed(state + 0x9e3779b97f4a7c15ULL)) >> 16); };
    for (int t = 0; t < 2000; ++t) {
        const std::uint32_t a = next();
        const int j = t % 32;
        const std::uint32_t b = j == 0 ? next() : ((a >> (32 - j)) << (32 - j)) | (next() >> j);
        const std::uint64_t seed = mix_seed(static_cast<std::uint64_t>(t) + 77);
        const std::uint32_t sa = owen_scramble(a, seed), sb = owen_scramble(b, seed);
        const int common = a == b ? 32 : __builtin_clz(a ^ b);
        const int scrambled_common = sa == sb ? 32 : __builtin_clz(sa ^ sb);
        REQUIRE(common == scrambled_common);
    }
    // Point 5 of a pair over 4096 seeds: 16 x 16 cells hold 16 each on average; chi-square with 255 degrees of
    // freedom stays below 370 with probability 1 - 1e-5.
    std::array<int, 256> cells{};
    for (std::uint64_t s = 0; s < 4096; ++s) {
        const Vec2 p = sobol_owen_pair(mix_seed(s + 1), 5);
        ++cells[static_cast<std::size_t>(std::floor(p.y * 16.0f) * 16.0f + std::floor(p.x * 16.0f))];
    }
    double chi2 = 0;
    for (int c : cells) chi2 += (c - 16.0) * (c - 16.0) / 16.0;
    CHECK(chi2 < 370.0);
}

TEST_CASE("every pair of every pixel is a progressive 02 sequence up to 1024 points", "[low_discrepancy]") {
    for (std::uint64_t seed : {0ULL, 1ULL, 0xfeedfaceULL}) {
        for (const auto& [x, y] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 0}, {17, 3}, {1023, 777}}) {
            for (std::uint32_t pair : {0u, 1u, 2u, 9u}) {
                const std::vector<Vec2> p = pair_points(seed, x, y, pair, 1024);
                for (int k = 0; k <= 10; ++k) {
                    INFO("seed " << seed << " pixel " << x << " " << y << " pair " << pair << " k " << k);
                    CHECK(is_02_net(p, 0, k));
                    // Progressive: every aligned block of 2^k after the first is a net too, so a prefix of any
                    // length is as well spread as the sequence allows (here the blocks of up to 64 points).
                    if (k <= 6)
                        for (std::size_t b = std::size_t{1} << k; b < p.size(); b += std::size_t{1} << k)
                            REQUIRE(is_02_net(p, b, k));
                }
            }
        }
    }
}

TEST_CASE("pixels seeds and pairs are decorrelated", "[low_discrepancy]") {
    const int n = 1024;
    // 64 neighbouring pixel pairs, same seed and pair: the correlation of their x (and y) coordinates, sample by
    // sample, is that of independent uniforms: sd 1/sqrt(1024) = 0.031 each, 0.004 for the mean over 64.
    double mean_r = 0, max_r = 0;
    std::set<float> firsts;
    for (std::uint32_t i = 0; i < 64; ++i) {
        const auto a = pair_points(3, i, 5, 0, n), b = pair_points(3, i + 1, 5, 0, n);
        std::vector<float> ax, bx, ay, by;
        for (int s = 0; s < n; ++s) {
            ax.push_back(a[static_cast<std::size_t>(s)].x), bx.push_back(b[static_cast<std::size_t>(s)].x);
            ay.push_back(a[static_cast<std::size_t>(s)].y), by.push_back(b[static_cast<std::size_t>(s)].y);
        }
        for (double r : {correlation(ax, bx), correlation(ay, by)}) {
            mean_r += r / 128.0;
            max_r = std::max(max_r, std::abs(r));
        }
        firsts.insert(a[0].x);
    }
    CHECK(std::abs(mean_r) < 0.02);
    CHECK(max_r < 0.16);         // 5 sd
    CHECK(firsts.size() == 64);  // the first sample is not shared by pixels
    // Seeds, and pairs of one pixel (the padding of higher dimensions): 4 x 4 cells of (one pair's x, another's
    // x) hold 64 points each on average; chi-square with 15 degrees of freedom below 45 with probability 1 - 1e-4.
    auto chi2 = [&](const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
        std::array<int, 16> cells{};
        for (std::size_t s = 0; s < a.size(); ++s)
            ++cells[static_cast<std::size_t>(std::floor(a[s].x * 4.0f) * 4.0f + std::floor(b[s].x * 4.0f))];
        double c2 = 0;
        for (int c : cells) c2 += (c - 64.0) * (c - 64.0) / 64.0;
        return c2;
    };
    CHECK(chi2(pair_points(1, 8, 8, 0, n), pair_points(2, 8, 8, 0, n)) < 45.0);
    CHECK(chi2(pair_points(1, 8, 8, 0, n), pair_points(1, 8, 8, 1, n)) < 45.0);
    CHECK(chi2(pair_points(1, 8, 8, 2, n), pair_points(1, 8, 8, 3, n)) < 45.0);
    CHECK(chi2(pair_points(1, 8, 8, 0, n), pair_points(1, 8, 9, 0, n)) < 45.0);
}

TEST_CASE("a smooth integrand converges much faster than with independent samples", "[low_discrepancy]") {
    // The integral of exp(-x y) over the unit square is Ein(1) = sum over k >= 1 of (-1)^(k+1) / (k k!).
    double exact = 0, term = 1;
    for (int k = 1; k < 20; ++k) {
        term /= k;
        exact += ((k % 2) ? 1.0 : -1.0) * term / k;
    }
    auto rmse = [&](SampleSequence sequence, int n) {
        // Over 64 pixels: 64 independent randomisations of the same estimator.
        double se = 0;
        for (std::uint32_t pixel = 0; pixel < 64; ++pixel) {
            double sum = 0;
            for (const Vec2& p : pair_points(11, pixel, 0, kFirstIntegratorPair, n, sequence))
                sum += std::exp(-static_cast<double>(p.x) * static_cast<double>(p.y));
            se += (sum / n - exact) * (sum / n - exact);
        }
        return std::sqrt(se / 64.0);
    };
    const double sobol_256 = rmse(SampleSequence::sobol, 256), sobol_1024 = rmse(SampleSequence::sobol, 1024);
    const double random_256 = rmse(SampleSequence::independent, 256);
    const double random_1024 = rmse(SampleSequence::independent, 1024);
    std::printf(
        "exp(-xy) RMSE over 64 pixels: 256 spp sobol %.3g random %.3g (ratio %.1f); 1024 spp sobol %.3g "
        "random %.3g (ratio %.1f)\n",
        sobol_256, random_256, random_256 / sobol_256, sobol_1024, random_1024, random_1024 / sobol_1024);
    // Independent samples: RMSE = sd / sqrt(n), halving from 256 to 1024; scrambled (0,2) points on a smooth
    // integrand: about n^-1.5, 8 times smaller.
    CHECK(random_256 / sobol_256 > 10.0);
    CHECK(random_1024 / sobol_1024 > 30.0);
    CHECK(sobol_256 / sobol_1024 > 4.0);
}

TEST_CASE("stream numbers are pure functions of sequence key and dimension", "[low_discrepancy]") {
    for (SampleSequence q : {SampleSequence::sobol, SampleSequence::independent}) {
        const SampleKey key{42, 7, 9, 13, 0};
        const SampleStream a(q, key), b(q, key);
        for (std::uint32_t d = 0; d < 40; ++d) {
            REQUIRE(a.get1d(d) == b.get1d(d));
            REQUIRE(a.get1d(d) == (d % 2 ? a.get2d(d / 2).y : a.get2d(d / 2).x));
            REQUIRE(a.get1d(d) >= 0.0f);
            REQUIRE(a.get1d(d) < 1.0f);
        }
        // Any field of the key changes the numbers.
        for (SampleKey other : {SampleKey{43, 7, 9, 13, 0}, SampleKey{42, 8, 9, 13, 0}, SampleKey{42, 7, 10, 13, 0},
                                SampleKey{42, 7, 9, 14, 0}, SampleKey{42, 7, 9, 13, 1}})
            CHECK(SampleStream(q, other).get2d(3) != a.get2d(3));
    }
    CHECK(SampleStream(SampleSequence::sobol, {1, 2, 3, 4, 0}).get2d(0) !=
          SampleStream(SampleSequence::independent, {1, 2, 3, 4, 0}).get2d(0));
}
