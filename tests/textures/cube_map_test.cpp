#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/textures/cube_map.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"
#include "skip.hpp"

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
const auto dir = test::scratch_dir("textures_cubemap");

// Face f is one colour: f + 1 in red, 10 (f + 1) in green.
RGB face_colour(int f) { return RGB(static_cast<float>(f + 1), 10.0f * static_cast<float>(f + 1), 0.0f); }

std::array<Image, 6> constant_faces(int n) {
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) faces[f] = Image(n, n, face_colour(f));
    return faces;
}

std::array<Image, 6> random_faces(int n, std::uint64_t seed) {
    Rng rng(seed);
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) {
        faces[f] = Image(n, n);
        for (RGB& p : faces[f].pixels()) p = RGB(rng.uniform(), rng.uniform(), rng.uniform());
    }
    return faces;
}

constexpr CubeFace kPlus[3] = {CubeFace::px, CubeFace::py, CubeFace::pz};
constexpr CubeFace kMinus[3] = {CubeFace::nx, CubeFace::ny, CubeFace::nz};

Vec3 axis(int a, float sign) {
    Vec3 v(0.0f);
    v[a] = sign;
    return v;
}

// The 12 edges: a pair of axes (a, b) with signs; the third axis c runs along the edge.
struct Edge {
    int a, b, c;
    float sa, sb;
};
std::vector<Edge> all_edges() {
    std::vector<Edge> edges;
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b)
            for (float sa : {1.0f, -1.0f})
                for (float sb : {1.0f, -1.0f}) edges.push_back({a, b, 3 - a - b, sa, sb});
    return edges;
}
CubeFace face_of(int a, float s) { return s > 0 ? kPlus[a] : kMinus[a]; }
int index(CubeFace f) { return static_cast<int>(f); }
}  // namespace

TEST_CASE("cube face selection for the 6 axes hits each face centre", "[cubemap]") {
    for (int a = 0; a < 3; ++a)
        for (float s : {1.0f, -1.0f}) {
            const CubeFaceCoord c = cube_face_coord(axis(a, s) * 3.0f);
            CHECK(c.face == face_of(a, s));
            CHECK(c.s == 0.5f);
            CHECK(c.t == 0.5f);
        }
    const CubeMapTexture map(constant_faces(4));
    for (int a = 0; a < 3; ++a)
        for (float s : {1.0f, -1.0f}) CHECK(map.sample(axis(a, s)) == face_colour(index(face_of(a, s))));
}

TEST_CASE("cube face coordinates follow the OpenGL table", "[cubemap]") {
    // (face, sc, tc) for d: px (-z, -y), nx (z, -y), py (x, z), ny (x, -z), pz (x, -y), nz (-x, -y); s = (sc + 1) / 2.
    struct Case {
        Vec3 d;
        CubeFace face;
        float s, t;
    };
    for (const Case& k :
         {Case{{1.0f, 0.5f, -0.5f}, CubeFace::px, 0.75f, 0.25f}, Case{{-1.0f, 0.5f, -0.5f}, CubeFace::nx, 0.25f, 0.25f},
          Case{{0.5f, 1.0f, -0.5f}, CubeFace::py, 0.75f, 0.25f}, Case{{0.5f, -1.0f, -0.5f}, CubeFace::ny, 0.75f, 0.75f},
          Case{{0.5f, 0.5f, 1.0f}, CubeFace::pz, 0.75f, 0.25f}, Case{{0.5f, 0.5f, -1.0f}, CubeFace::nz, 0.25f, 0.25f},
          Case{{2.0f, -1.0f, 1.0f}, CubeFace::px, 0.25f, 0.75f}}) {
        INFO("d = " << k.d.x << " " << k.d.y << " " << k.d.z);
        const CubeFaceCoord c = cube_face_coord(k.d);
        CHECK(c.face == k.face);
        CHECK(c.s == k.s);
        CHECK(c.t == k.t);
        // The inverse gives a direction parallel to d.
        const Vec3 back = cube_face_direction(c.face, c.s, c.t);
        CHECK(glm::length(glm::cross(glm::normalize(back), glm::normalize(k.d))) < 1e-6f);
    }
    // Round trip for points spread over every face.
    Rng rng(3);
    for (int n = 0; n < 600; ++n) {
        const auto f = static_cast<CubeFace>(n % 6);
        const float s = rng.uniform(), t = rng.uniform();
        const CubeFaceCoord c = cube_face_coord(cube_face_direction(f, s, t));
        REQUIRE(c.face == f);
        REQUIRE(c.s == Approx(s).margin(1e-6));
        REQUIRE(c.t == Approx(t).margin(1e-6));
    }
}

TEST_CASE("the 12 edge directions give the mean of the two faces and corners the mean of three", "[cubemap]") {
    const CubeMapTexture map(constant_faces(8));
    for (const Edge& e : all_edges()) {
        const Vec3 d = axis(e.a, e.sa) + axis(e.b, e.sb);
        const RGB expected = (face_colour(index(face_of(e.a, e.sa))) + face_colour(index(face_of(e.b, e.sb)))) * 0.5f;
        INFO("edge " << d.x << " " << d.y << " " << d.z);
        const RGB got = map.sample(d);
        CHECK(got.r == Approx(expected.r).epsilon(1e-6));
        CHECK(got.g == Approx(expected.g).epsilon(1e-6));
        // Points along the edge as well, not only the midpoint.
        for (float w : {-0.8f, -0.3f, 0.6f}) {  // away from the corners (within 1 - 1/N)
            const RGB along = map.sample(d + axis(e.c, w));
            CHECK(along.r == Approx(expected.r).epsilon(1e-6));
        }
    }
    for (float sx : {1.0f, -1.0f})
        for (float sy : {1.0f, -1.0f})
            for (float sz : {1.0f, -1.0f}) {
                const RGB expected = (face_colour(index(face_of(0, sx))) + face_colour(index(face_of(1, sy))) +
                                      face_colour(index(face_of(2, sz)))) *
                                     (1.0f / 3.0f);
                const RGB got = map.sample({sx, sy, sz});
                CHECK(got.r == Approx(expected.r).epsilon(1e-5));
                CHECK(got.g == Approx(expected.g).epsilon(1e-5));
            }
}

TEST_CASE("a cube map of random texels is continuous across every edge", "[cubemap]") {
    const CubeMapTexture map(random_faces(8, 5));
    const float delta = 1e-5f;
    float worst = 0.0f, typical = 0.0f;
    int samples = 0;
    for (const Edge& e : all_edges()) {
        for (int k = 0; k <= 40; ++k) {
            const float w = -0.98f + 1.96f * static_cast<float>(k) / 40.0f;
            const Vec3 d = axis(e.a, e.sa) + axis(e.b, e.sb) + axis(e.c, w);
            // Slightly onto face a (larger |a| component) and slightly onto face b.
            const Vec3 on_a = d + axis(e.a, e.sa * delta), on_b = d + axis(e.b, e.sb * delta);
            REQUIRE(cube_face_coord(on_a).face == face_of(e.a, e.sa));
            REQUIRE(cube_face_coord(on_b).face == face_of(e.b, e.sb));
            const RGB ga = map.sample(on_a), gb = map.sample(on_b);
            for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(ga[ch] - gb[ch]));
            // For scale: the jump a seam would make, face a's own edge texel against face b's.
            const Vec3 inner_a = d - axis(e.b, e.sb * 0.2f);
            typical += std::abs(map.sample(inner_a).r - gb.r);
            ++samples;
        }
    }
    INFO("worst jump across an edge " << worst << ", mean difference a fifth of a face apart " << typical / samples);
    CHECK(worst < 1e-3f);
    CHECK(typical / samples > 0.05f);
}

TEST_CASE("a horizontal cross gives the same map as six faces", "[cubemap]") {
    const int n = 4;
    const auto faces = random_faces(n, 9);
    Image cross(4 * n, 3 * n, RGB(-1.0f));
    const int cell[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};  // px nx py ny pz nz
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) cross.at(cell[f][0] * n + x, cell[f][1] * n + y) = faces[f].at(x, y);
    write_image(cross, dir / "cross.pfm");
    const auto from_cross = CubeMapTexture::load_cross(dir / "cross.pfm");
    const CubeMapTexture from_faces(faces);
    Rng rng(21);
    for (int k = 0; k < 500; ++k) {
        const Vec3 d(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f);
        REQUIRE(from_cross->sample(d) == from_faces.sample(d));
    }
    // Through the registry with six files and with a folder.
    std::array<std::filesystem::path, 6> paths;
    const char* names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    Params six;
    for (int f = 0; f < 6; ++f) {
        paths[f] = dir / (std::string(names[f]) + ".pfm");
        write_image(faces[f], paths[f]);
        six.set(names[f], paths[f].string());
    }
    const TextureRegistry r = make_texture_registry();
    const auto t6 = r.create("cubemap", six);
    const auto tf = r.create("cubemap", Params{}.set("folder", dir.string()).set("extension", std::string("pfm")));
    const auto tc = r.create("cubemap", Params{}.set("cross", (dir / "cross.pfm").string()).set("intensity", 2.0));
    for (int k = 0; k < 100; ++k) {
        TextureLookup q;
        q.direction = {rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f};
        REQUIRE(t6->eval(q) == from_faces.sample(q.direction));
        REQUIRE(tf->eval(q) == from_faces.sample(q.direction));
        REQUIRE(tc->eval(q) == from_faces.sample(q.direction) * 2.0f);
    }
    // A zero or non-finite direction is black, not a crash.
    CHECK(from_faces.sample(Vec3(0.0f)) == RGB(0.0f));
    CHECK(from_faces.sample(Vec3(std::nanf(""), 1.0f, 0.0f)) == RGB(0.0f));
}

TEST_CASE("cube map size errors name the face or the file", "[cubemap]") {
    auto faces = constant_faces(4);
    faces[3] = Image(4, 5);
    CHECK_THROWS_WITH(CubeMapTexture(faces), Contains("face 'ny'") && Contains("not square"));
    faces[3] = Image(8, 8);
    CHECK_THROWS_WITH(CubeMapTexture(faces), Contains("face 'ny'") && Contains("same size"));
    write_image(Image(10, 6), dir / "bad_cross.pfm");
    CHECK_THROWS_WITH(CubeMapTexture::load_cross(dir / "bad_cross.pfm"),
                      Contains("bad_cross.pfm") && Contains("4N x 3N"));
    const TextureRegistry r = make_texture_registry();
    CHECK_THROWS_WITH(r.create("cubemap", Params{}.set("folder", (dir / "nowhere").string())),
                      Contains("texture 'cubemap'") && Contains("px.jpg"));
    CHECK_THROWS_WITH(r.create("cubemap", Params{}.set("cross", std::string("a.png")).set("px", std::string("b.png"))),
                      Contains("exactly one"));
}

TEST_CASE("the shared star-field skybox lines up across its face edges", "[cubemap]") {
    const auto shared = test::shared_dir();
    if (!shared || !std::filesystem::exists(*shared / "textures" / "skybox" / "px.jpg"))
        return test::skip(test::needs_shared("textures/skybox"));
    const TextureRegistry r = make_texture_registry();
    const auto sky = r.create("cubemap", Params{}.set("folder", (*shared / "textures" / "skybox").string()));
    const auto* map = dynamic_cast<const CubeMapTexture*>(sky.get());
    REQUIRE(map != nullptr);
    CHECK(map->face_size() == 1024);
    // With the stated convention, the texels on either side of each edge show neighbouring sky. Compare
    // the edge column of face a with face b's edge column (matched) and with a shifted one (unmatched):
    // matched pairs must differ much less.
    const int n = map->face_size();
    double matched = 0.0, shifted = 0.0;
    for (const Edge& e : all_edges()) {
        for (int k = 0; k < n; ++k) {
            const float w = -1.0f + 2.0f * (static_cast<float>(k) + 0.5f) / static_cast<float>(n);
            const float in = 1.0f - 1.0f / static_cast<float>(n);  // the centre of the edge texel
            auto lum = [&](const Vec3& d) { return static_cast<double>(map->sample(d).luminance()); };
            const Vec3 base = axis(e.c, w);
            const double a = lum(axis(e.a, e.sa) + axis(e.b, e.sb * in) + base);
            const double b = lum(axis(e.a, e.sa * in) + axis(e.b, e.sb) + base);
            const float w2 = -1.0f + 2.0f * (static_cast<float>((k + n / 3) % n) + 0.5f) / static_cast<float>(n);
            const double b_shift = lum(axis(e.a, e.sa * in) + axis(e.b, e.sb) + axis(e.c, w2));
            matched += std::abs(a - b);
            shifted += std::abs(a - b_shift);
        }
    }
    INFO("mean |difference| across edges: matched " << matched / (12 * n) << ", shifted " << shifted / (12 * n));
    CHECK(matched < 0.7 * shifted);
}
