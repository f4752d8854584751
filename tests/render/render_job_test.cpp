#include "image_bytes.hpp"
#include "scene_fixtures.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/render_job.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

using namespace rtlab;
using namespace rtlab::test;

namespace {

std::shared_ptr<const Shape> quad_x(float x0, float x1, float z) {
    return std::make_shared<Quad>(Point3(x0, -1, z), Vec3(x1 - x0, 0, 0), Vec3(0, 2, 0));
}

}  // namespace

TEST_CASE("a render job without camera or scene or with a null light is an error", "[render_job]") {
    RenderJob job;
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{});
    CHECK_THROWS_WITH(render_job(job), Catch::Contains("no camera"));
    job.camera = std::make_shared<PinholeCamera>(CameraSpec{.width = 4, .height = 4});
    job.lights = {point_light(Point3(0.0f), 1.0f), nullptr};
    CHECK_THROWS_WITH(render_job(job), Catch::Contains("light 1 is null"));
    job.lights.clear();
    job.scene.reset();
    CHECK_THROWS_WITH(render_job(job), Catch::Contains("no scene"));
}

TEST_CASE("a lit Lambert sphere renders the radiance computed by hand", "[render_job]") {
    // Camera and point light at (0, 0, 5), unit sphere at the origin, albedo 0.5, physical convention:
    // L = 0.5 / pi * I cos(theta) / d^2, computed here in double for every pixel's centre ray; I = 16 pi
    // makes the centre pixel (d = 4, cos = 1) exactly 0.5. Pixels whose ray passes within 1e-3 of the
    // silhouette are left out (float and double may disagree on hit or miss there).
    const float intensity = 16.0f * kPi;
    RenderJob job;
    job.scene = std::make_shared<Scene>(
        std::vector<SceneObject>{{std::make_shared<Sphere>(Point3(0.0f), 1.0f), lambert(RGB(0.5f)), {}, "ball"}});
    const auto camera = std::make_shared<PinholeCamera>(
        CameraSpec{.eye = {0, 0, 5}, .look_at = {0, 0, 0}, .vertical_fov_degrees = 30.0f, .width = 41, .height = 41});
    job.camera = camera;
    job.lights = {point_light(Point3(0, 0, 5), intensity)};
    job.whitted.background = RGB(0.25f, 0.5f, 0.75f);
    const RenderResult r = render_job(job);
    CHECK(r.image.at(20, 20).r == Approx(0.5f).epsilon(1e-5));
    int lit = 0, background = 0, checked = 0;
    double worst = 0.0;
    for (int y = 0; y < 41; ++y) {
        for (int x = 0; x < 41; ++x) {
            const Ray ray = camera->ray(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            const glm::dvec3 o(ray.origin), d = glm::normalize(glm::dvec3(ray.direction));
            const double b = glm::dot(o, d), c = glm::dot(o, o) - 1.0, disc = b * b - c;
            const RGB& got = r.image.at(x, y);
            if (std::abs(disc) < 1e-3) continue;
            ++checked;
            if (disc < 0.0) {
                ++background;
                CHECK(got == RGB(0.25f, 0.5f, 0.75f));
                continue;
            }
            const glm::dvec3 p = o + (-b - std::sqrt(disc)) * d, to_light = glm::dvec3(0, 0, 5) - p;
            const double d2 = glm::dot(to_light, to_light);
            const double want = 0.5 / kPi * intensity * std::max(0.0, glm::dot(p, to_light) / std::sqrt(d2)) / d2;
            worst = std::max(worst, std::abs(got.r - want) / want);
            CHECK(got.r == got.g);
            CHECK(got.g == got.b);
            ++lit;
        }
    }
    INFO("worst relative error " << worst);
    CHECK(worst < 2e-5);
    CHECK(lit > 200);
    CHECK(background > 200);
    CHECK(checked > 1500);
    // One shadow ray per lit pixel and nothing else: the sphere cannot shadow itself towards the camera.
    CHECK(r.stats.rays.camera == 41 * 41);
    CHECK(r.stats.rays.shadow >= static_cast<std::uint64_t>(lit));
    CHECK(r.stats.rays.reflected == 0);
    CHECK(r.stats.rays.refracted == 0);
}

TEST_CASE("statistics count every kind of ray on a scene counted by hand", "[render_job]") {
    // A 4 x 1 image; at z = -10 the four pixel rays meet, left to right: a Lambert quad (1 shadow ray to
    // the light at the eye), a mirror (1 reflected ray, back past the eye into the background), a glass
    // pane (Fresnel: 1 reflected ray that escapes and 1 refracted ray that reaches a Lambert wall at
    // z = -20, whose shadow ray crosses the pane: 2 shadow segments), nothing. With a list and a tree.
    for (std::size_t threshold : {kAlwaysList, std::size_t{1}}) {
        RenderJob job;
        job.scene = std::make_shared<Scene>(
            std::vector<SceneObject>{{quad_x(-3.5f, -1.75f, -10), lambert(RGB(0.5f)), {}, "diffuse"},
                                     {quad_x(-1.75f, 0.0f, -10), material("mirror"), {}, "mirror"},
                                     {quad_x(0.0f, 1.75f, -10), material("glass"), {}, "pane"},
                                     {quad_x(0.5f, 2.0f, -20), lambert(RGB(0.5f)), {}, "wall"}},
            SceneOptions{threshold});
        job.camera =
            std::make_shared<PinholeCamera>(CameraSpec{.vertical_fov_degrees = 10.0f, .width = 4, .height = 1});
        job.lights = {point_light(Point3(0.0f), 100.0f)};
        job.whitted.background = RGB(0.1f, 0.2f, 0.3f);
        const RenderResult r = render_job(job);
        CHECK(r.stats.rays.camera == 4);
        CHECK(r.stats.rays.shadow == 3);
        CHECK(r.stats.rays.reflected == 2);
        CHECK(r.stats.rays.refracted == 1);
        CHECK(r.stats.rays.total() == 10);
        CHECK(r.image.at(3, 0) == RGB(0.1f, 0.2f, 0.3f));
        CHECK(r.image.at(1, 0) == RGB(0.1f, 0.2f, 0.3f));  // a perfect mirror of the background
        CHECK(r.image.at(0, 0).r > 0.0f);
        CHECK(r.image.at(2, 0).r > 0.03f);  // the lit wall through the pane (~0.038), plus 4 % of the background
    }
}

TEST_CASE("a render job gives the same image and counts for 1 and 2 threads", "[render_job]") {
    RenderJob job;
    job.scene = std::make_shared<Scene>(random_objects(60, 20, 5));
    job.camera = std::make_shared<PinholeCamera>(
        CameraSpec{.eye = {0, 3, 2}, .look_at = {0, 1.5f, -10}, .width = 48, .height = 40});
    job.lights = {point_light(Point3(-3, 8, 0), 300.0f)};
    for (PixelPattern p : {PixelPattern::jittered, PixelPattern::adaptive, PixelPattern::sobol}) {
        INFO(pixel_pattern_name(p));
        job.settings.pattern = p;
        job.settings.spp = 2;
        job.settings.threads = 1;
        const RenderResult one = render_job(job);
        job.settings.threads = 2;
        const RenderResult two = render_job(job);
        CHECK(same_bytes(one.image, two.image));
        CHECK(one.stats.rays == two.stats.rays);
        CHECK(one.stats.rays.reflected > 0);
        CHECK(one.stats.rays.refracted > 0);
    }
}
