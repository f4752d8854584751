// make_area_emitter(): the surface an object's area light samples is the object's own, facing the way its hits
// say the outside faces, through instances (mirroring ones too) and the reversed flag.
#include "scene_fixtures.hpp"

#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/geometry/sphere.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <rtlab/geometry/disk.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/render/sampled_lights.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace rtlab;
using namespace rtlab::test;

namespace {

std::shared_ptr<const Material> emitting() {
    Params p;
    p.set("albedo", 0.0).set("emission", 2.0);
    return material("lambert", p);
}

// From points around the object, every light sample lies on the shape (a ray towards it hits there) and on the
// emitting side, and the shape's emitting side is lit from somewhere.
// Points come from the cube of half-size `spread` around `centre` (inside a sphere that emits inwards).
void check_object(const SceneObject& object, const Point3& centre = Point3(0.0f), float spread = 2.0f) {
    const auto emitter = make_area_emitter(object);
    REQUIRE(emitter != nullptr);
    Rng rng(9);
    int samples = 0;
    for (int i = 0; i < 200; ++i) {
        const Point3 p = centre + spread * (2.0f * Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 1.0f);
        const auto s = emitter->sample_li(p, rng.uniform2());
        if (!s) continue;
        ++samples;
        SurfaceHit hit;
        REQUIRE(object.shape->intersect(Ray{p, s->wi, 0.0f, kInfinity}, hit));
        INFO(object.name << " from " << p.x << " " << p.y << " " << p.z);
        CHECK(glm::length(hit.point - s->position) < 1e-3f);
        const Normal3 outward = object.flags.reversed ? -hit.geometric_normal : hit.geometric_normal;
        CHECK(glm::dot(s->wi, outward) < 0.0f);  // the sample arrives at the emitting (outer) face
        const float pdf = emitter->pdf_li(p, s->wi, hit.point, outward);
        CHECK(pdf == Approx(s->pdf).epsilon(1e-3));
    }
    CHECK(samples > 40);
}

}  // namespace

TEST_CASE("area lights sample the object's own surface on its emitting side", "[sampled_lights]") {
    const Mat4 mirror = glm::scale(Mat4(1.0f), Vec3(-1.0f, 1.0f, 1.0f));
    const Mat4 placed = glm::rotate(glm::translate(Mat4(1.0f), Vec3(0.2f, 0.1f, 0.0f)), 0.7f, Vec3(1, 1, 0));
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->positions = {{-0.5f, 0, -0.5f},
                       {0.5f, 0, -0.5f},
                       {0.7f, 0, 0.5f},
                       {-0.5f, 0, 0.4f}};  // flat (no part hides another), not a parallelogram
    mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
    const auto mesh_shape = std::make_shared<MeshShape>(mesh);
    const auto quad = std::make_shared<Quad>(Point3(-0.4f, 0, -0.3f), Vec3(0.8f, 0, 0), Vec3(0, 0.2f, 0.6f));
    const auto disk = std::make_shared<Disk>(Point3(0, 0.1f, 0), Normal3(0.3f, 1, 0), 0.5f);
    for (bool reversed : {false, true}) {
        const SurfaceFlags flags{true, reversed};
        DYNAMIC_SECTION("reversed " << reversed) {
            check_object({mesh_shape, emitting(), flags, "mesh"});
            check_object({std::make_shared<Instance>(mesh_shape, placed * mirror), emitting(), flags, "mirrored mesh"});
            check_object({quad, emitting(), flags, "quad"});
            check_object({std::make_shared<Instance>(quad, mirror), emitting(), flags, "mirrored quad"});
            check_object({disk, emitting(), flags, "disk"});
            check_object({std::make_shared<Instance>(disk, placed * mirror), emitting(), flags, "mirrored disk"});
            const Mat4 sphere_to_world = placed * glm::scale(Mat4(1.0f), Vec3(1.5f));  // radius 0.6
            const Point3 centre(sphere_to_world * glm::vec4(0.1f, 0.0f, 0.0f, 1.0f));
            check_object(
                {std::make_shared<Instance>(std::make_shared<Sphere>(Point3(0.1f, 0, 0), 0.4f), sphere_to_world),
                 emitting(), flags, "scaled sphere"},
                centre, reversed ? 0.3f : 2.0f);
        }
    }
}

TEST_CASE("an object of textured or no emission has no area light", "[sampled_lights]") {
    CHECK(make_area_emitter({std::make_shared<Sphere>(Point3(0.0f), 1.0f), lambert(RGB(0.5f)), {}, "plain"}) ==
          nullptr);
}
