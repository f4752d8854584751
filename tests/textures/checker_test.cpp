#include <rtlab/textures/texture.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace rtlab;

namespace {
const TextureRegistry& registry() {
    static const TextureRegistry r = make_texture_registry();
    return r;
}

// Checker with colour1 = 1 (even) and colour2 = 0 (odd): the red channel is 1 on even tiles.
float even(const Texture& t, float u, float v) { return t.eval(TextureLookup{{u, v}, {}, {}}).r; }
float even3(const Texture& t, float x, float y, float z) { return t.eval(TextureLookup{{}, {x, y, z}, {}}).r; }
}  // namespace

TEST_CASE("checker parity at tile borders belongs to the tile above and holds for negative uv", "[checker]") {
    // 4 tiles per unit in u, 2 in v: tile (floor(4u), floor(2v)).
    const auto t = registry().create("checker", Params{}.set("tiles_u", 4.0).set("tiles_v", 2.0));
    CHECK(even(*t, 0.0f, 0.0f) == 1.0f);                         // (0, 0)
    CHECK(even(*t, 0.25f, 0.0f) == 0.0f);                        // exactly on the border: (1, 0)
    CHECK(even(*t, std::nextafter(0.25f, 0.0f), 0.0f) == 1.0f);  // just below: (0, 0)
    CHECK(even(*t, 0.25f, 0.5f) == 1.0f);                        // (1, 1)
    CHECK(even(*t, 0.0f, 0.5f) == 0.0f);                         // (0, 1)
    CHECK(even(*t, -0.25f, 0.0f) == 0.0f);                       // on a negative border: (-1, 0)
    CHECK(even(*t, -0.01f, 0.0f) == 0.0f);                       // (-1, 0)
    CHECK(even(*t, -0.26f, 0.0f) == 1.0f);                       // (-2, 0)
    CHECK(even(*t, -0.01f, -0.01f) == 1.0f);                     // (-1, -1)
    CHECK(even(*t, -0.5f, -0.5f) == 0.0f);                       // (-2, -1)
    CHECK(even(*t, 0.3f, -1.0f) == 0.0f);                        // (1, -2): odd
    // Far out the parity still alternates tile by tile: 2^20 tiles in is (2^20, 0), even; one more is odd.
    CHECK(even(*t, 262144.0f, 0.1f) == 1.0f);
    CHECK(even(*t, 262144.25f, 0.1f) == 0.0f);
    CHECK(even(*t, -262144.25f, 0.1f) == 0.0f);
    // Non-finite uv does not crash; it is shown as an even tile.
    CHECK(even(*t, std::nanf(""), 0.0f) == 1.0f);
}

TEST_CASE("checker parity equals the fmod rule for far and non-finite uv", "[checker]") {
    // The rule the parity shortcut replaces: |fmod(i, 2)| + |fmod(j, 2)| == 1 is odd.
    auto expected = [](double tu, double tv, float u, float v) {
        const double i = std::floor(static_cast<double>(u) * tu), j = std::floor(static_cast<double>(v) * tv);
        return std::abs(std::fmod(i, 2.0)) + std::abs(std::fmod(j, 2.0)) == 1.0 ? 0.0f : 1.0f;
    };
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<float> values{0.0f,
                                    -0.0f,
                                    0.3f,
                                    -0.3f,
                                    1e7f,
                                    -1e7f,
                                    16777215.0f,
                                    1e15f,
                                    -1e15f,
                                    1e16f,
                                    -1e16f,
                                    9e15f,
                                    1e30f,
                                    -1e30f,
                                    3.4e38f,
                                    inf,
                                    -inf,
                                    std::nanf(""),
                                    4503599627370495.5f,
                                    0x1p52f,
                                    0x1p53f,
                                    -0x1p53f,
                                    0x1.fffffep52f,
                                    -0x1.fffffep52f,
                                    0x1p-140f};
    int odd = 0;
    for (const double tiles : {1.0, 3.0, 7.0, 16777215.0}) {
        const auto t =
            registry().create("checker", Params{}.set("tiles_u", tiles).set("tiles_v", tiles == 1.0 ? 5.0 : 1.0));
        const double tv = tiles == 1.0 ? 5.0 : 1.0;
        for (const float u : values)
            for (const float v : values) {
                const float e = expected(tiles, tv, u, v);
                CHECK(even(*t, u, v) == e);
                odd += e == 0.0f ? 1 : 0;
            }
    }
    CHECK(odd > 100);  // the values reach odd tiles too, not only the even fallback
}

TEST_CASE("checker counts tiles per unit and defaults tiles_v to tiles_u", "[checker]") {
    const auto t = registry().create("checker", Params{}.set("tiles_u", 3.0));
    int changes = 0;
    float last = even(*t, 0.0005f, 0.1f);
    for (int k = 1; k < 1000; ++k) {
        const float e = even(*t, (k + 0.5f) / 1000.0f, 0.1f);
        changes += e != last ? 1 : 0;
        last = e;
    }
    CHECK(changes == 2);                                 // 3 tiles across [0, 1]
    CHECK(even(*t, 0.1f, 1.0f / 3.0f + 1e-4f) == 0.0f);  // v also has 3 tiles per unit
    const auto d = registry().create("checker", Params{});
    CHECK(even(*d, 0.124f, 0.0f) == 1.0f);  // default 8 per unit
    CHECK(even(*d, 0.126f, 0.0f) == 0.0f);
}

TEST_CASE("checker selects between two nested textures", "[checker]") {
    const auto inner = registry().create("checker", Params{}.set("tiles_u", 40.0).set("tiles_v", 40.0));
    Params p;
    p.set("tiles_u", 1.0).set("color2", Params::List{0.0, 0.0, 1.0});
    p.set_object<Texture>("color1", inner);
    const auto t = registry().create("checker", p);
    CHECK(t->eval(TextureLookup{{0.01f, 0.01f}, {}, {}}) == RGB(1.0f));     // outer even, inner (0, 0) even
    CHECK(t->eval(TextureLookup{{0.03f, 0.01f}, {}, {}}) == RGB(0.0f));     // outer even, inner (1, 0) odd
    CHECK(t->eval(TextureLookup{{1.03f, 0.01f}, {}, {}}) == RGB(0, 0, 1));  // outer odd: colour 2
}

TEST_CASE("checker3d parity in object space including faces and negative coordinates", "[checker]") {
    const auto t = registry().create("checker3d", Params{}.set("tiles", 2.0));  // cells of 0.5
    CHECK(even3(*t, 0.1f, 0.1f, 0.1f) == 1.0f);                                 // (0, 0, 0)
    CHECK(even3(*t, 0.5f, 0.1f, 0.1f) == 0.0f);                                 // on the face x = 0.5: (1, 0, 0)
    CHECK(even3(*t, 0.5f, 0.5f, 0.1f) == 1.0f);                                 // (1, 1, 0)
    CHECK(even3(*t, 0.5f, 0.5f, 0.5f) == 0.0f);                                 // (1, 1, 1)
    CHECK(even3(*t, -0.1f, 0.1f, 0.1f) == 0.0f);                                // (-1, 0, 0)
    CHECK(even3(*t, -0.1f, -0.1f, -0.1f) == 0.0f);                              // (-1, -1, -1)
    CHECK(even3(*t, -0.5f, -0.1f, 0.0f) == 1.0f);  // x = -0.5 is on a face, cell -1: (-1, -1, 0)
    CHECK(even3(*t, -0.6f, -0.1f, 0.0f) == 0.0f);  // (-2, -1, 0)
    // uv is ignored.
    CHECK(t->eval(TextureLookup{{0.7f, 0.2f}, {0.1f, 0.1f, 0.1f}, {}}).r == 1.0f);
    // Per-axis tiles: 1 cell per unit in x, 10 in y, 1 in z.
    const auto a = registry().create("checker3d", Params{}.set("tiles", Params::List{1, 10, 1}));
    CHECK(even3(*a, 0.5f, 0.05f, 0.5f) == 1.0f);
    CHECK(even3(*a, 0.5f, 0.15f, 0.5f) == 0.0f);
    CHECK(even3(*a, 0.9f, 0.05f, 0.5f) == 1.0f);
}
