#include <rtlab/geometry/box.hpp>
#include <rtlab/geometry/cylinder.hpp>
#include <rtlab/geometry/disk.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/spawn.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/geometry/triangle_shape.hpp>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "spawn_check.hpp"
#include "test_meshes.hpp"

using namespace rtlab;
using namespace rtlab::spawn_check;

namespace {

constexpr int kSources = 500;  // x 4 outward, 4 inward, up to 2 connection rays

std::vector<std::shared_ptr<const Shape>> triangles_of(const std::shared_ptr<const TriangleMesh>& mesh) {
    std::vector<std::shared_ptr<const Shape>> out;
    for (std::uint32_t i = 0; i < mesh->triangle_count(); ++i) out.push_back(std::make_shared<TriangleShape>(mesh, i));
    return out;
}

// A rotation and a non-uniform scale (x1, x0.5, x2) of size s, moved to the scale's place.
Mat4 placement(const Scale& s) {
    Mat4 m = glm::translate(Mat4(1.0f), place(s));
    m = glm::rotate(m, 0.7f, glm::normalize(Vec3(1, 2, 3)));
    return glm::scale(m, s.size * Vec3(1.0f, 0.5f, 2.0f));
}

// Runs one shape kind at every scale, prints the counts and requires zero failures of the spawned rays.
// The fixed-epsilon control must fail somewhere, or the harness could not see a failure.
void run_all(const char* kind, const std::function<Case(const Scale&)>& make, bool control_fails = true) {
    print_header();
    Counts total;
    std::uint32_t seed = 1;
    for (const Scale& s : scales()) {
        const Case c = make(s);
        const Counts k = run(c, kSources, seed++);
        print(std::string(kind) + " " + s.name, k);
        INFO(kind << " at scale " << s.name);
        CHECK(k.outward >= 4 * kSources);
        if (s.mixed) {
            CHECK(k.failures() <= k.failures_fixed());
        } else {
            CHECK(k.outward_fail == 0);
            CHECK(k.inward_fail == 0);
            CHECK(k.connect_fail == 0);
        }
        total.add(k);
    }
    print(std::string(kind) + " all", total);
    if (control_fails) CHECK(total.failures_fixed() > 0);
}

}  // namespace

TEST_CASE("offset_ray_origin moves by the error bound along the normal to the side the ray leaves", "[spawn]") {
    const Point3 p(1.0f, 2.0f, -3.0f);
    const Vec3 err(1e-3f, 2e-3f, 4e-3f);
    const Normal3 n(0.0f, 1.0f, 0.0f);
    // d = |n| . err = 2e-3 along y, then one float step further; x and z stay put.
    const Point3 out = offset_ray_origin(p, err, n, Vec3(0.3f, 0.2f, 0.0f));
    CHECK(out.x == p.x);
    CHECK(out.z == p.z);
    CHECK(out.y == std::nextafter(p.y + 2e-3f, kInfinity));
    const Point3 in = offset_ray_origin(p, err, n, Vec3(0.3f, -0.2f, 0.0f));
    CHECK(in.y == std::nextafter(p.y - 2e-3f, -kInfinity));
    // A tangent direction goes to the normal's side; a zero bound still leaves the surface by one step.
    CHECK(offset_ray_origin(p, err, n, Vec3(1, 0, 0)).y > p.y);
    CHECK(offset_ray_origin(p, Vec3(0.0f), n, Vec3(0, -1, 0)).y == std::nextafter(p.y, -kInfinity));
    // A slanted normal moves every axis it leans along, by dot(|n|, err) in all.
    const Normal3 s = glm::normalize(Vec3(1, -1, 0));
    const Point3 o = offset_ray_origin(Point3(0.0f), Vec3(1e-3f), s, s);
    CHECK(o.x > 0.0f);
    CHECK(o.y < 0.0f);
    CHECK(o.z == 0.0f);
    CHECK(glm::length(o) == Approx(std::sqrt(2.0f) * 1e-3f).epsilon(1e-5));
}

TEST_CASE("spawn_step_up is nextafter towards +inf on every kind of float", "[spawn]") {
    const float inf = std::numeric_limits<float>::infinity();
    const float max = std::numeric_limits<float>::max();
    const float tiny = std::numeric_limits<float>::denorm_min();
    const float normal = std::numeric_limits<float>::min();
    int checked = 0;
    for (float x :
         {0.0f,  -0.0f,  tiny, -tiny, normal, -normal, 1.0f,        -1.0f,        0.3f,          -0.3f,
          1e30f, -1e30f, max,  -max,  inf,    -inf,    2.0f * tiny, -2.0f * tiny, normal - tiny, -(normal - tiny)}) {
        INFO(x);
        const float want = std::nextafter(x, inf);
        CHECK(std::bit_cast<std::uint32_t>(spawn_step_up(x)) == std::bit_cast<std::uint32_t>(want));
        CHECK(std::bit_cast<std::uint32_t>(-spawn_step_up(-x)) ==
              std::bit_cast<std::uint32_t>(std::nextafter(x, -inf)));
        ++checked;
    }
    CHECK(checked == 20);
    CHECK(std::isnan(spawn_step_up(std::numeric_limits<float>::quiet_NaN())));
    // nextafter(-tiny, +inf) is -0: the same bits as next_float_up gives.
    CHECK(std::bit_cast<std::uint32_t>(spawn_step_up(-tiny)) == std::bit_cast<std::uint32_t>(next_float_up(-tiny)));
}

TEST_CASE("spawn_ray and spawn_ray_to set the range and stop short of the target", "[spawn]") {
    const Sphere sphere(Point3(0.0f), 1.0f);
    SurfaceHit hit;
    REQUIRE(sphere.intersect(Ray{{0, 0, 5}, {0, 0, -1}}, hit));
    const Ray r = spawn_ray(hit, Vec3(0, 0, 1));
    CHECK(r.tmin == 0.0f);
    CHECK(r.tmax == kInfinity);
    CHECK(r.origin.z > 1.0f);
    const Point3 light(0, 0, 3);
    const Ray s = spawn_ray_to(hit, light);
    CHECK(s.tmax == 1.0f - kShadowEpsilon);
    CHECK(glm::length(s.origin + s.direction - light) < 1e-6f);
    // Between two hits: both ends offset to the inside (the segment is a chord), the end short of `to`.
    SurfaceHit back;
    REQUIRE(sphere.intersect(Ray{{0, 0, -5}, {0, 0, 1}}, back));
    const Ray c = spawn_ray_to(hit, back);
    CHECK(c.origin.z < 1.0f);
    CHECK((c.origin + c.direction).z > -1.0f);
    CHECK_FALSE(sphere.occluded(c));
}

TEST_CASE("every shape reports its error bound and its object point", "[spawn]") {
    const Ray down{{0.25f, 0.3f, 10.0f}, {0.0f, 0.0f, -1.0f}};
    const std::shared_ptr<const Shape> shapes[] = {
        std::make_shared<Sphere>(Point3(0.0f), 1.0f), std::make_shared<Box>(AABB{Point3(-1.0f), Point3(1.0f)}),
        std::make_shared<Quad>(Point3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)),
        std::make_shared<Disk>(Point3(0.0f), Normal3(0, 0, 1), 1.0f),
        std::make_shared<Cylinder>(Point3(0, 0, -1), Point3(0, 0, 1), 1.0f)};
    int checked = 0;
    for (const auto& s : shapes) {
        SurfaceHit h;
        REQUIRE(s->intersect(down, h));
        CHECK(h.shape == s.get());
        CHECK(h.object_point == h.point);
        // Within a few float steps of the naive point, never negative, never more than 1e-5 at this scale.
        CHECK(glm::length(h.point - down.at(h.t)) < 1e-5f);
        CHECK(min_component(h.point_error) >= 0.0f);
        CHECK(max_component(h.point_error) < 1e-5f);
        ++checked;
    }
    CHECK(checked == 5);
    // The box snaps its point onto the face: exact, a zero bound.
    SurfaceHit h;
    REQUIRE(shapes[1]->intersect(down, h));
    CHECK(h.point.z == 1.0f);
    CHECK(h.point_error == Vec3(0.0f));
    // The sphere's point lies on the sphere to within its bound.
    REQUIRE(shapes[0]->intersect(Ray{{0.3f, -0.2f, 7.0f}, {-0.01f, 0.03f, -1.0f}}, h));
    CHECK(std::abs(glm::length(glm::dvec3(h.point)) - 1.0) <= glm::length(glm::dvec3(h.point_error)));
}

TEST_CASE("through an Instance the hit names the instance and keeps the inner primitive and point", "[spawn]") {
    auto mesh = std::make_shared<TriangleMesh>(test::icosphere(1));
    const auto tri = std::make_shared<TriangleShape>(mesh, 7);
    const auto group = std::make_shared<Group>(std::vector<std::shared_ptr<const Shape>>{
        std::make_shared<Sphere>(Point3(0.0f), 0.5f), std::make_shared<Sphere>(Point3(3, 0, 0), 0.5f)});
    const Mat4 m =
        glm::scale(glm::rotate(glm::translate(Mat4(1.0f), Vec3(10, 20, 30)), 0.4f, Vec3(0, 1, 0)), Vec3(2.0f));
    const Instance a(group, m), b(group, glm::translate(Mat4(1.0f), Vec3(-50, 0, 0)));
    const Point3 target = Point3(m * Vec4(0.1f, 0.2f, 0.3f, 1.0f));
    SurfaceHit h;
    REQUIRE(a.intersect(Ray{target + Vec3(0, 0, 20), Vec3(0, 0, -1)}, h));
    CHECK(h.shape == &a);
    const Point3 inner = Point3(glm::inverse(m) * Vec4(h.point, 1.0f));
    CHECK(glm::length(h.object_point - inner) < 1e-4f);
    CHECK(glm::length(h.object_point) == Approx(0.5f).epsilon(1e-5));
    SurfaceHit g;
    REQUIRE(b.intersect(Ray{{-50, 0, 5}, {0, 0, -1}}, g));
    CHECK(g.shape == &b);  // one inner group, two instances, two shapes (for two materials)
    CHECK(g.object_point.z == Approx(0.5f));
    // The inner triangle's index survives the instance.
    const Instance ti(tri, glm::translate(Mat4(1.0f), Vec3(0, 0, 5)));
    const Point3 c = (mesh->corner(7, 0) + mesh->corner(7, 1) + mesh->corner(7, 2)) / 3.0f + Vec3(0, 0, 5);
    const Vec3 n =
        glm::normalize(glm::cross(mesh->corner(7, 1) - mesh->corner(7, 0), mesh->corner(7, 2) - mesh->corner(7, 0)));
    REQUIRE(ti.intersect(Ray{c + 3.0f * n, -n}, h));
    CHECK(h.primitive == 7u);
    CHECK(h.shape == &ti);
    CHECK(glm::length(h.object_point - (c - Vec3(0, 0, 5))) < 1e-5f);
}

TEST_CASE("spawned rays on spheres never re-hit them and find the far side at every scale", "[spawn]") {
    run_all("sphere", [](const Scale& s) {
        const Point3 c = place(s);
        return Case{"sphere", {std::make_shared<Sphere>(c, s.size)}, sphere_span(c, s.size), c, s.size};
    });
}

TEST_CASE("spawned rays on boxes of quads and on Box shapes at every scale", "[spawn]") {
    run_all("quad box", [](const Scale& s) {
        const Point3 c = place(s);
        std::vector<Plane> planes;
        Point3 hi = c + Vec3(0.5f * s.size);
        auto quads = quad_box(c - Vec3(0.5f * s.size), hi, &planes);
        return Case{"quad box", quads, polytope_span(planes), c, s.size};
    });
    run_all("box", [](const Scale& s) {
        const Point3 c = place(s);
        std::vector<Plane> planes;
        Point3 hi = c + Vec3(0.5f * s.size);
        quad_box(c - Vec3(0.5f * s.size), hi, &planes);
        const AABB b{c - Vec3(0.5f * s.size), hi};
        return Case{"box", {std::make_shared<Box>(b)}, polytope_span(planes), c, s.size};
    });
}

TEST_CASE("spawned rays on triangle meshes: a rotated cube of 12 and an icosphere of 320", "[spawn]") {
    run_all("triangle cube", [](const Scale& s) {
        auto mesh = std::make_shared<TriangleMesh>(cube_mesh(placement(s)));
        return Case{"triangle cube", triangles_of(mesh), polytope_span(mesh_planes(*mesh)), place(s), 2.0f * s.size};
    });
    run_all("icosphere", [](const Scale& s) {
        auto mesh = std::make_shared<TriangleMesh>(test::icosphere(2, s.size, place(s)));
        return Case{"icosphere", triangles_of(mesh), polytope_span(mesh_planes(*mesh)), place(s), s.size};
    });
}

TEST_CASE("spawned rays on tilted capped cylinders at every scale", "[spawn]") {
    run_all("cylinder", [](const Scale& s) {
        const Vec3 axis = glm::normalize(Vec3(0.3f, 1.0f, -0.5f));
        const Point3 c = place(s), base = c - 0.5f * s.size * axis, top = c + 0.5f * s.size * axis;
        return Case{"cylinder",
                    {std::make_shared<Cylinder>(base, top, 0.4f * s.size)},
                    cylinder_span(base, top, 0.4f * s.size),
                    c,
                    s.size};
    });
}

TEST_CASE("spawned rays on instances with rotation and scale at every scale", "[spawn]") {
    run_all("instance sphere", [](const Scale& s) {
        const Mat4 m = placement(s);
        auto unit = std::make_shared<Sphere>(Point3(0.0f), 1.0f);
        return Case{"instance sphere",
                    {std::make_shared<Instance>(unit, m)},
                    transformed_span(sphere_span(Point3(0.0f), 1.0f), m),
                    place(s),
                    2.0f * s.size};
    });
    run_all("instance quad box", [](const Scale& s) {
        const Mat4 m = placement(s);
        std::vector<Plane> planes;
        Point3 hi(0.5f);
        auto quads = std::make_shared<Group>(quad_box(Point3(-0.5f), hi, &planes));
        return Case{"instance quad box",
                    {std::make_shared<Instance>(quads, m)},
                    transformed_span(polytope_span(planes), m),
                    place(s),
                    2.0f * s.size};
    });
    run_all("instance triangle cube", [](const Scale& s) {
        const Mat4 m = placement(s);
        auto mesh = std::make_shared<TriangleMesh>(cube_mesh(Mat4(1.0f)));
        auto group = std::make_shared<Group>(triangles_of(mesh));
        return Case{"instance triangle cube",
                    {std::make_shared<Instance>(group, m)},
                    transformed_span(polytope_span(mesh_planes(*mesh)), m),
                    place(s),
                    2.0f * s.size};
    });
}

TEST_CASE("spawned rays from flat quads and disks hit nothing on either side at every scale", "[spawn]") {
    run_all("quad", [](const Scale& s) {
        const Point3 c = place(s);
        const Vec3 u = s.size * Vec3(0.8f, 0.3f, -0.2f), v = s.size * Vec3(-0.1f, 0.4f, 0.9f);
        return Case{"quad", {std::make_shared<Quad>(c - 0.5f * (u + v), u, v)}, {}, c, s.size};
    });
    run_all("disk", [](const Scale& s) {
        const Point3 c = place(s);
        return Case{"disk", {std::make_shared<Disk>(c, Normal3(0.2f, -0.7f, 0.5f), s.size)}, {}, c, s.size};
    });
}
