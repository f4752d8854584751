#include <rtlab/core/error.hpp>
#include <rtlab/core/sample_hash.hpp>
#include <rtlab/render/thin_lens_camera.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace rtlab;

namespace {
const CameraSpec kSpec{.eye = {0.5f, 1.0f, 8.0f},
                       .look_at = {0.0f, 0.0f, 0.0f},
                       .up = {0, 1, 0},
                       .vertical_fov_degrees = 40.0f,
                       .width = 64,
                       .height = 48};

/// Where the ray meets the plane at `depth` along the camera's forward axis from the eye.
Point3 at_depth(const Ray& r, const PinholeCamera& pin, float depth) {
    const Point3 plane_point = pin.spec().eye + depth * pin.forward();
    const float t = glm::dot(plane_point - r.origin, pin.forward()) / glm::dot(r.direction, pin.forward());
    return r.at(t);
}

std::vector<Vec2> lens_samples(int n) {
    std::vector<Vec2> out = {{0.0f, 0.0f}, {0.999f, 0.5f}, {0.5f, 0.0f}, {0.5f, 0.5f}};
    for (int i = 0; i < n; ++i) out.push_back(sample_uniform2(SampleKey{1, 0, 0, static_cast<std::uint32_t>(i), 0}, 0));
    return out;
}
}  // namespace

TEST_CASE("a thin lens with aperture 0 gives exactly the pinhole rays", "[camera]") {
    const ThinLensCamera lens(kSpec, {.aperture = 0.0f, .focus_distance = 3.0f});
    const PinholeCamera pin(kSpec);
    for (Vec2 p : {Vec2(0, 0), Vec2(31.5f, 20.25f), Vec2(64, 48)}) {
        for (Vec2 u : lens_samples(8)) {
            const Ray a = lens.generate_ray(p, u);
            const Ray b = pin.ray(p.x, p.y);
            CHECK(a.origin == b.origin);
            CHECK(a.direction == b.direction);
        }
    }
}

TEST_CASE("the thin lens focus plane is sharp and other depths spread by the circle of confusion", "[camera]") {
    const float aperture = 0.4f, focus = 5.0f;
    const ThinLensCamera lens(kSpec, {.aperture = aperture, .focus_distance = focus});
    const PinholeCamera& pin = lens.pinhole();
    const auto samples = lens_samples(256);
    for (Vec2 p : {Vec2(32, 24), Vec2(0.5f, 0.5f), Vec2(63.5f, 3.25f)}) {
        INFO("image position " << p.x << ", " << p.y);
        const Point3 sharp = at_depth(pin.ray(p.x, p.y), pin, focus);
        float focus_spread = 0.0f, near_spread = 0.0f, far_spread = 0.0f;
        const Point3 near0 = at_depth(lens.generate_ray(p, samples[0]), pin, 2.5f);
        const Point3 far0 = at_depth(lens.generate_ray(p, samples[0]), pin, 15.0f);
        for (Vec2 u : samples) {
            const Ray r = lens.generate_ray(p, u);
            CHECK(std::abs(glm::length(r.direction) - 1.0f) < 1e-6f);
            // The ray starts on the lens disc, in the plane through the eye facing forward.
            const Vec3 offset = r.origin - pin.spec().eye;
            CHECK(std::abs(glm::dot(offset, pin.forward())) < 1e-6f);
            CHECK(glm::length(offset) <= 0.5f * aperture * (1.0f + 1e-6f));
            focus_spread = std::max(focus_spread, glm::length(at_depth(r, pin, focus) - sharp));
            near_spread = std::max(near_spread, glm::length(at_depth(r, pin, 2.5f) - near0));
            far_spread = std::max(far_spread, glm::length(at_depth(r, pin, 15.0f) - far0));
        }
        // Every lens sample meets the focus plane at the pinhole ray's point (float rounding only).
        CHECK(focus_spread < 2e-5f * focus);
        // Off the focus plane the blur has diameter aperture * |d - f| / f (world units at depth d); the
        // spread from one sample to the others is at most that and, with 260 samples, close to it.
        const float near_coc = aperture * (focus - 2.5f) / focus, far_coc = aperture * (15.0f - focus) / focus;
        CHECK(near_spread <= near_coc * 1.0001f);
        CHECK(near_spread > 0.9f * near_coc);
        CHECK(far_spread <= far_coc * 1.0001f);
        CHECK(far_spread > 0.9f * far_coc);
    }
}

TEST_CASE("focus distance 0 focuses on look_at", "[camera]") {
    const ThinLensCamera lens(kSpec, {.aperture = 1.0f});
    CHECK(lens.focus_distance() == Approx(glm::length(kSpec.look_at - kSpec.eye)));
    // look_at is at the image centre, so every lens sample's central ray passes through it.
    for (Vec2 u : lens_samples(32)) {
        const Ray r = lens.generate_ray({32.0f, 24.0f}, u);
        const Vec3 to = kSpec.look_at - r.origin;
        CHECK(glm::length(glm::cross(glm::normalize(to), r.direction)) < 1e-5f);
    }
}

TEST_CASE("a thin lens gives back its aperture and focus distance", "[camera]") {
    // What a program needs to make the same lens again at another position (rtlab-view's orbit).
    const ThinLensCamera lens(kSpec, {.aperture = 0.25f, .focus_distance = 3.0f});
    CHECK(lens.aperture() == 0.25f);
    CHECK(lens.focus_distance() == 3.0f);
    const ThinLensCamera again(kSpec, {.aperture = lens.aperture(), .focus_distance = lens.focus_distance()});
    CHECK(again.generate_ray({10.0f, 20.0f}, {0.3f, 0.7f}).origin ==
          lens.generate_ray({10.0f, 20.0f}, {0.3f, 0.7f}).origin);
}

TEST_CASE("concentric disc map stays in the unit disc and covers it evenly", "[camera]") {
    int quadrant[4] = {0, 0, 0, 0};
    int inner = 0;
    const int n = 4096;
    for (int i = 0; i < n; ++i) {
        const Vec2 d = concentric_disc(sample_uniform2(SampleKey{3, 0, 0, static_cast<std::uint32_t>(i), 0}, 0));
        REQUIRE(glm::length(d) <= 1.0f + 1e-6f);
        quadrant[(d.x >= 0 ? 0 : 1) + (d.y >= 0 ? 0 : 2)]++;
        inner += glm::length(d) < std::sqrt(0.5f);  // half the area
    }
    for (int q : quadrant) CHECK(std::abs(q - n / 4) < 120);
    CHECK(std::abs(inner - n / 2) < 150);
    CHECK(concentric_disc({0.5f, 0.5f}) == Vec2(0.0f));
    CHECK(glm::length(concentric_disc({0.0f, 0.5f})) == Approx(1.0f));
}

TEST_CASE("bad lenses are rejected with a reason", "[camera]") {
    using Catch::Matchers::Contains;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK_THROWS_WITH(ThinLensCamera(kSpec, {.aperture = -0.1f}), Contains("aperture"));
    CHECK_THROWS_WITH(ThinLensCamera(kSpec, {.aperture = nan}), Contains("aperture"));
    CHECK_THROWS_WITH(ThinLensCamera(kSpec, {.aperture = 0.1f, .focus_distance = -1.0f}), Contains("focus"));
    CHECK_THROWS_WITH(
        ThinLensCamera(kSpec, {.aperture = 0.1f, .focus_distance = std::numeric_limits<float>::infinity()}),
        Contains("focus"));
    CHECK_THROWS_WITH(ThinLensCamera({.width = -2}, {}), Contains("image size"));
}
