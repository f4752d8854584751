#include "orbit_camera.hpp"

#include <rtlab/scene/scene_loader.hpp>

#include <catch2/catch.hpp>

using namespace rtlab;
using namespace rtlab::view;

namespace {
PinholeCamera file_camera() {
    CameraSpec spec;
    spec.eye = Point3(0.0f, 2.0f, 4.0f);
    spec.look_at = Point3(0.0f, 0.9f, -2.5f);
    spec.vertical_fov_degrees = 45.0f;
    spec.width = 64;
    spec.height = 48;
    return PinholeCamera(spec);
}
}  // namespace

TEST_CASE("orbiting keeps the distance to the look-at point and a full turn comes back", "[view]") {
    OrbitCamera camera(file_camera());
    REQUIRE(camera.movable());
    const float distance = glm::length(camera.spec().eye - camera.spec().look_at);
    camera.orbit(0.7f, 0.2f);
    CHECK(camera.changed());
    CHECK(glm::length(camera.spec().eye - camera.spec().look_at) == Approx(distance).epsilon(1e-5));
    camera.orbit(-0.7f, -0.2f);
    CHECK(glm::length(camera.spec().eye - file_camera().spec().eye) < 1e-4f);
}

TEST_CASE("orbiting stops short of the poles", "[view]") {
    OrbitCamera camera(file_camera());
    camera.orbit(0.0f, 10.0f);
    const Vec3 dir = glm::normalize(camera.spec().eye - camera.spec().look_at);
    CHECK(dir.y < 1.0f);
    CHECK(dir.y > 0.999f);
    CHECK_NOTHROW(PinholeCamera(camera.spec()));
}

TEST_CASE("panning moves eye and look-at together and reset restores the file's camera", "[view]") {
    OrbitCamera camera(file_camera());
    const Vec3 offset = camera.spec().eye - camera.spec().look_at;
    camera.pan(0.5f, 0.25f);
    CHECK(glm::length(camera.spec().eye - camera.spec().look_at - offset) < 1e-5f);
    CHECK(camera.spec().look_at != file_camera().spec().look_at);
    camera.dolly(0.5f);
    CHECK(glm::length(camera.spec().eye - camera.spec().look_at) == Approx(0.5f * glm::length(offset)).epsilon(1e-5));
    camera.reset();
    CHECK_FALSE(camera.changed());
}

TEST_CASE("the camera snippet loads back as the same camera", "[view]") {
    OrbitCamera camera(file_camera());
    camera.orbit(0.3f, 0.1f);
    const std::string scene =
        "{\"version\": 1, " + camera.json_snippet() +
        ", \"render\": {\"width\": 64, \"height\": 48}, \"shapes\": [{\"type\": \"sphere\", \"visible\": false}]}";
    const LoadedScene loaded = parse_scene(scene, "snippet.json");
    const auto* pinhole = dynamic_cast<const PinholeCamera*>(loaded.job.camera.get());
    REQUIRE(pinhole);
    CHECK(pinhole->spec().eye == camera.spec().eye);
    CHECK(pinhole->spec().look_at == camera.spec().look_at);
    CHECK(pinhole->spec().vertical_fov_degrees == camera.spec().vertical_fov_degrees);
}
