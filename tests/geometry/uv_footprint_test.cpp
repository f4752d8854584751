// Each shape's own uv footprint (Shape::uv_footprint) against the functions a scene loader and
// rtlab-solar-system worked it out with from the shape's numbers (sphere_footprint, disk_footprint): bit for
// bit, so that the texture levels "lod": "auto" picks, and the images made with them, do not change.
#include <rtlab/core/rng.hpp>
#include <rtlab/geometry/box.hpp>
#include <rtlab/geometry/disk.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/geometry/uv_footprint.hpp>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <bit>
#include <cstdint>
#include <optional>

using namespace rtlab;

namespace {

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

bool same_bits(const std::optional<UvFootprint>& got, const UvFootprint& want) {
    return got && same_bits(got->centre.x, want.centre.x) && same_bits(got->centre.y, want.centre.y) &&
           same_bits(got->centre.z, want.centre.z) && same_bits(got->radius, want.radius) &&
           same_bits(got->u_length, want.u_length);
}

float in(Rng& rng, float lo, float hi) { return lo + (hi - lo) * rng.uniform(); }

Point3 random_point(Rng& rng) { return {in(rng, -50, 50), in(rng, -50, 50), in(rng, -50, 50)}; }

// A rotation, a non-uniform scale and a translation, as a scene's "transform" composes them.
Mat4 random_transform(Rng& rng) {
    Mat4 m = glm::translate(Mat4(1.0f), Vec3(random_point(rng)));
    m = glm::rotate(m, in(rng, -3.0f, 3.0f), glm::normalize(Vec3(in(rng, -1, 1), in(rng, -1, 1), 1.0f)));
    return glm::scale(m, Vec3(in(rng, 0.01f, 30.0f), in(rng, 0.01f, 30.0f), in(rng, 0.01f, 30.0f)));
}

}  // namespace

TEST_CASE("a sphere's uv footprint is sphere_footprint's bit for bit placed or not", "[uv_footprint]") {
    Rng rng(20);
    for (int i = 0; i < 2000; ++i) {
        const Point3 centre = random_point(rng);
        const float radius = in(rng, 1e-3f, 100.0f);
        const auto sphere = std::make_shared<Sphere>(centre, radius);
        const Mat4 m = random_transform(rng);
        INFO("case " << i);
        CHECK(same_bits(sphere->uv_footprint(), sphere_footprint(Mat4(1.0f), centre, radius)));
        CHECK(same_bits(Instance(sphere, m).uv_footprint(), sphere_footprint(m, centre, radius)));
    }
    // The planets of rtlab-solar-system: a unit sphere at the origin under the planet's matrix.
    const Mat4 planet = glm::scale(glm::translate(Mat4(1.0f), Vec3(30.0f, 0.0f, -4.0f)), Vec3(0.4f));
    CHECK(same_bits(Instance(std::make_shared<Sphere>(Point3(0.0f), 1.0f), planet).uv_footprint(),
                    sphere_footprint(planet, Point3(0.0f), 1.0f)));
}

TEST_CASE("a disk's uv footprint is disk_footprint's bit for bit placed or not", "[uv_footprint]") {
    Rng rng(21);
    for (int i = 0; i < 2000; ++i) {
        const Point3 centre = random_point(rng);
        const float radius = in(rng, 1e-3f, 100.0f);
        const float inner = i % 3 == 0 ? 0.0f : radius * in(rng, 0.0f, 0.99f);
        const auto disk = std::make_shared<Disk>(centre, Normal3(in(rng, -1, 1), 1.0f, in(rng, -1, 1)), radius, inner);
        const Mat4 m = random_transform(rng);
        INFO("case " << i);
        CHECK(same_bits(disk->uv_footprint(), disk_footprint(Mat4(1.0f), centre, radius, inner)));
        CHECK(same_bits(Instance(disk, m).uv_footprint(), disk_footprint(m, centre, radius, inner)));
    }
}

TEST_CASE("an instance of an instance composes the matrices outer times inner", "[uv_footprint]") {
    Rng rng(22);
    const auto sphere = std::make_shared<Sphere>(Point3(1.0f, 2.0f, 3.0f), 0.5f);
    const Mat4 inner = random_transform(rng), outer = random_transform(rng);
    const Instance twice(std::make_shared<Instance>(sphere, inner), outer);
    CHECK(same_bits(twice.uv_footprint(), sphere_footprint(outer * inner, Point3(1.0f, 2.0f, 3.0f), 0.5f)));
}

TEST_CASE("shapes without one uv footprint give none and so do their instances", "[uv_footprint]") {
    const auto quad = std::make_shared<Quad>(Point3(0.0f), Vec3(1, 0, 0), Vec3(0, 0, 1));
    const auto box = std::make_shared<Box>(AABB{Point3(0.0f), Point3(1.0f)});
    CHECK_FALSE(quad->uv_footprint());
    CHECK_FALSE(box->uv_footprint());
    CHECK_FALSE(Instance(quad, glm::scale(Mat4(1.0f), Vec3(2.0f))).uv_footprint());
}
