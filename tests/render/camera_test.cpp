#include <rtlab/core/error.hpp>
#include <rtlab/render/camera.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace rtlab;

TEST_CASE("the camera reproduces the primary ray set of FORMATS.md", "[camera]") {
    // Box [-1, 3]^3: c = (1, 1, 1), diag = 4 sqrt(3); eye = c + (0, 0, 1.5 diag), looking along -z.
    const Point3 c{1, 1, 1};
    const float diag = 4.0f * std::sqrt(3.0f);
    const int n = 64;
    const PinholeCamera cam({.eye = c + Vec3(0, 0, 1.5f * diag),
                             .look_at = c,
                             .up = {0, 1, 0},
                             .vertical_fov_degrees = 45.0f,
                             .width = n,
                             .height = n});
    const float th = std::tan(22.5f * kPi / 180.0f);
    for (int j : {0, 7, 31, 63}) {
        for (int i : {0, 13, 32, 63}) {
            const float px = (2.0f * (i + 0.5f) / n - 1.0f) * th;
            const float py = (1.0f - 2.0f * (j + 0.5f) / n) * th;
            const Vec3 expected = glm::normalize(Vec3(px, py, -1.0f));
            const Ray r = cam.ray(i + 0.5f, j + 0.5f);
            INFO("pixel " << i << ", " << j);
            CHECK(glm::length(r.direction - expected) < 1e-6f);
            CHECK(r.origin == c + Vec3(0, 0, 1.5f * diag));
        }
    }
}

TEST_CASE("image centre looks at look_at and corners span the field of view", "[camera]") {
    const PinholeCamera cam({.eye = {5, 2, 0},
                             .look_at = {0, 2, 0},
                             .up = {0, 1, 0},
                             .vertical_fov_degrees = 60.0f,
                             .width = 200,
                             .height = 100});
    const Ray centre = cam.ray(100.0f, 50.0f);
    CHECK(glm::length(centre.direction - Vec3(-1, 0, 0)) < 1e-6f);
    // Top edge centre: 30 degrees above the view direction.
    const Ray top = cam.ray(100.0f, 0.0f);
    CHECK(std::acos(glm::dot(top.direction, Vec3(-1, 0, 0))) == Approx(kPi / 6.0f).epsilon(1e-5));
    CHECK(top.direction.y > 0.0f);
    // Right edge: the horizontal half-angle follows from the aspect ratio 2.
    const Ray right = cam.ray(200.0f, 50.0f);
    CHECK(std::atan2(std::abs(right.direction.z), -right.direction.x) ==
          Approx(std::atan(2.0f * std::tan(kPi / 6.0f))).epsilon(1e-5));
}

TEST_CASE("invalid cameras are rejected with a reason", "[camera]") {
    using Catch::Matchers::Contains;
    CHECK_THROWS_WITH(PinholeCamera({.eye = {0, 0, 0}, .look_at = {0, 5, 0}, .up = {0, 1, 0}}), Contains("parallel"));
    CHECK_THROWS_WITH(PinholeCamera({.eye = {0, 0, 0}, .look_at = {0, 0, 0}}), Contains("must differ"));
    CHECK_THROWS_WITH(PinholeCamera({.vertical_fov_degrees = 180.0f}), Contains("field of view"));
    CHECK_THROWS_WITH(PinholeCamera({.width = 0}), Contains("image size"));
}

TEST_CASE("the pinhole camera interface ignores the lens sample", "[camera]") {
    const PinholeCamera cam({.eye = {1, 2, 3}, .look_at = {0, 0, 0}, .width = 40, .height = 30});
    const Camera& base = cam;
    CHECK(base.width() == 40);
    CHECK(base.height() == 30);
    const Ray a = base.generate_ray({12.25f, 7.5f}, {0.9f, 0.1f});
    const Ray b = cam.ray(12.25f, 7.5f);
    CHECK(a.origin == b.origin);
    CHECK(a.direction == b.direction);
}
