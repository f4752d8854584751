#include <rtlab/accel/ray_io.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
const auto dir = test::scratch_dir("accel_rays");
}

TEST_CASE("ray and hit files round-trip exactly", "[rays]") {
    const std::vector<Ray> rays = {Ray{{1, 2, 3}, {0, -0.0f, 1}, 0.5f, kInfinity},
                                   Ray{{-1e6f, 0, 1e-30f}, {3, 4, 5}, 0, 7}};
    write_ray_file(dir / "r.rays", rays);
    const auto back = read_ray_file(dir / "r.rays");
    REQUIRE(back.size() == 2);
    CHECK(back[1].origin == rays[1].origin);
    CHECK(back[0].tmax == kInfinity);
    CHECK(std::signbit(back[0].direction.y));
    CHECK(std::filesystem::file_size(dir / "r.rays") == 16 + 32 * 2);
    const std::vector<MeshHit> hits = {MeshHit{1.5f, 7, 0.25f, 0.5f}, MeshHit{}};
    write_hit_file(dir / "h.hits", hits);
    const auto hb = read_hit_file(dir / "h.hits");
    REQUIRE(hb.size() == 2);
    CHECK(hb[0].primitive == 7);
    CHECK(hb[0].v == 0.5f);
    CHECK(hb[1].t == kInfinity);
    CHECK(hb[1].primitive == 0xFFFFFFFFu);
}

TEST_CASE("malformed ray files are rejected with the file name", "[rays]") {
    write_ray_file(dir / "good.rays", std::vector<Ray>(3));
    auto bytes = read_binary_file(dir / "good.rays");
    auto write = [&](const char* name, std::vector<unsigned char> b) {
        write_binary_file(dir / name, b);
        return dir / name;
    };
    auto truncated = bytes;
    truncated.pop_back();
    CHECK_THROWS_WITH(read_ray_file(write("short.rays", truncated)),
                      Contains("short.rays") && Contains("does not hold"));
    auto extra = bytes;
    extra.push_back(0);
    CHECK_THROWS_WITH(read_ray_file(write("long.rays", extra)), Contains("does not hold"));
    auto magic = bytes;
    magic[0] = 'X';
    CHECK_THROWS_WITH(read_ray_file(write("magic.rays", magic)), Contains("not a ray file"));
    auto huge = bytes;
    for (int i = 8; i < 16; ++i) huge[i] = 0xFF;  // a count of 2^64 - 1
    CHECK_THROWS_WITH(read_ray_file(write("huge.rays", huge)), Contains("does not hold"));
    CHECK_THROWS_WITH(read_ray_file(write("tiny.rays", {'R', 'T'})), Contains("shorter than its 16-byte header"));
    CHECK_THROWS_WITH(read_ray_file(dir / "absent.rays"), Contains("absent.rays"));
}

TEST_CASE("spawn files round-trip exactly with every int32 value", "[rays]") {
    const std::vector<std::int32_t> triangles = {0, 7, -1, std::numeric_limits<std::int32_t>::max(),
                                                 std::numeric_limits<std::int32_t>::min()};
    write_spawn_file(dir / "s.spawn", triangles);
    CHECK(std::filesystem::file_size(dir / "s.spawn") == 16 + 4 * 5);
    const auto bytes = read_binary_file(dir / "s.spawn");
    CHECK(std::string(bytes.begin(), bytes.begin() + 8) == "RTSPAWN1");
    CHECK(bytes[8] == 5);
    CHECK(bytes[16 + 4] == 7);  // little-endian
    CHECK(read_spawn_file(dir / "s.spawn") == triangles);
    write_spawn_file(dir / "empty.spawn", std::vector<std::int32_t>{});
    CHECK(read_spawn_file(dir / "empty.spawn").empty());
}

TEST_CASE("malformed spawn files are rejected with the file name", "[rays]") {
    write_spawn_file(dir / "good.spawn", std::vector<std::int32_t>{1, 2, 3});
    const auto bytes = read_binary_file(dir / "good.spawn");
    auto write = [&](const char* name, std::vector<unsigned char> b) {
        write_binary_file(dir / name, b);
        return dir / name;
    };
    auto truncated = bytes;
    truncated.pop_back();
    CHECK_THROWS_WITH(read_spawn_file(write("short.spawn", truncated)),
                      Contains("short.spawn") && Contains("does not hold the 3 records") && Contains("16 + 4 N"));
    auto extra = bytes;
    extra.insert(extra.end(), {0, 0, 0, 0});  // one whole record more than the header claims
    CHECK_THROWS_WITH(read_spawn_file(write("long.spawn", extra)), Contains("long.spawn") && Contains("does not hold"));
    auto huge = bytes;
    for (int i = 8; i < 16; ++i) huge[i] = 0xFF;  // 4 * count overflows 64 bits
    CHECK_THROWS_WITH(read_spawn_file(write("huge.spawn", huge)), Contains("does not hold"));
    auto quarter = bytes;
    quarter[15] = 0x40;  // 2^62 + 3 records: 4 N wraps to 12, the payload's size
    CHECK_THROWS_WITH(read_spawn_file(write("wrap.spawn", quarter)), Contains("does not hold"));
    // A ray file of one ray is 48 bytes, as a spawn file of 8 would be: the magic tells them apart.
    write_ray_file(dir / "one.rays", std::vector<Ray>(1));
    CHECK_THROWS_WITH(read_spawn_file(dir / "one.rays"), Contains("one.rays") && Contains("not a spawn file"));
    CHECK_THROWS_WITH(read_ray_file(dir / "good.spawn"), Contains("good.spawn") && Contains("not a ray file"));
    CHECK_THROWS_WITH(read_spawn_file(write("tiny.spawn", {'R', 'T', 'S'})),
                      Contains("tiny.spawn") && Contains("shorter than its 16-byte header"));
    CHECK_THROWS_WITH(read_spawn_file(dir / "absent.spawn"), Contains("absent.spawn"));
}

TEST_CASE("the primary ray set follows FORMATS.md", "[rays]") {
    const AABB b{{-1, -1, -1}, {1, 1, 1}};
    const auto rays = primary_rays(b, 4);
    REQUIRE(rays.size() == 16);
    const float diag = std::sqrt(12.0f);
    const float th = std::tan(22.5f * kPi / 180.0f);
    CHECK(rays[0].origin == Point3(0, 0, 1.5f * diag));
    // Pixel (i, j) = (0, 0), top left: px = (2 * 0.5 / 4 - 1) th, py = (1 - 2 * 0.5 / 4) th.
    const Vec3 d0 = glm::normalize(Vec3(-0.75f * th, 0.75f * th, -1.0f));
    CHECK(glm::length(rays[0].direction - d0) < 1e-7f);
    // Ray k = j N + i: k = 6 is (i, j) = (2, 1).
    const Vec3 d6 = glm::normalize(Vec3(0.25f * th, 0.25f * th, -1.0f));
    CHECK(glm::length(rays[6].direction - d6) < 1e-7f);
    CHECK(rays[0].tmin == 0.0f);
    CHECK(rays[0].tmax == kInfinity);
}

TEST_CASE("the random ray set follows FORMATS.md draw for draw", "[rays]") {
    const AABB b{{0, 0, 0}, {2, 4, 6}};
    const auto rays = random_rays(b, 3, 12345);
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> U(0, 1);
    const Point3 c(1, 2, 3);
    const float R = 1.5f * std::sqrt(4.0f + 16.0f + 36.0f) / 2.0f;
    for (const Ray& ray : rays) {
        const float u1 = U(rng), u2 = U(rng);
        const float z = 1 - 2 * u1, phi = 2 * kPi * u2, r = std::sqrt(std::max(0.0f, 1 - z * z));
        const Point3 o = c + R * Vec3(r * std::cos(phi), r * std::sin(phi), z);
        const float a = U(rng), bb = U(rng), e = U(rng);
        const Point3 q(2 * a, 4 * bb, 6 * e);
        CHECK(glm::length(ray.origin - o) < 1e-6f);
        CHECK(glm::length(ray.direction - glm::normalize(q - o)) < 1e-6f);
        CHECK(std::abs(glm::length(ray.origin - c) - R) < 1e-4f);
    }
}
