#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/geometry/instance.hpp>

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "../geometry/spawn_check.hpp"
#include "test_meshes.hpp"

using namespace rtlab;
using namespace rtlab::spawn_check;

// The re-intersection test of tests/geometry/spawn_test.cpp on meshes intersected through a kd-tree
// (MeshShape, kd-sah): the same rays must give the same answers as the triangles one by one.
namespace {

constexpr int kSources = 500;

Mat4 placement(const Scale& s) {
    Mat4 m = glm::translate(Mat4(1.0f), place(s));
    m = glm::rotate(m, 0.7f, glm::normalize(Vec3(1, 2, 3)));
    return glm::scale(m, s.size * Vec3(1.0f, 0.5f, 2.0f));
}

void run_all(const char* kind, const std::function<Case(const Scale&)>& make) {
    print_header();
    Counts total;
    std::uint32_t seed = 101;
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
    CHECK(total.failures_fixed() > 0);
}

}  // namespace

TEST_CASE("spawned rays on kd-tree meshes never re-hit them at every scale", "[spawn]") {
    run_all("mesh icosphere", [](const Scale& s) {
        auto mesh = std::make_shared<TriangleMesh>(test::icosphere(3, s.size, place(s)));
        return Case{
            "mesh icosphere", {std::make_shared<MeshShape>(mesh)}, polytope_span(mesh_planes(*mesh)), place(s), s.size};
    });
    run_all("mesh cube", [](const Scale& s) {
        auto mesh = std::make_shared<TriangleMesh>(cube_mesh(placement(s)));
        return Case{"mesh cube",
                    {std::make_shared<MeshShape>(mesh)},
                    polytope_span(mesh_planes(*mesh)),
                    place(s),
                    2.0f * s.size};
    });
}

TEST_CASE("spawned rays on instances of a kd-tree mesh with rotation and scale at every scale", "[spawn]") {
    auto sphere = std::make_shared<TriangleMesh>(test::icosphere(3));
    auto shared = std::make_shared<MeshShape>(sphere);
    run_all("instance mesh icosphere", [&](const Scale& s) {
        const Mat4 m = placement(s);
        return Case{"instance mesh icosphere",
                    {std::make_shared<Instance>(shared, m)},
                    transformed_span(polytope_span(mesh_planes(*sphere)), m),
                    place(s),
                    2.0f * s.size};
    });
    // Two instances of one mesh: the hit names the instance it came through.
    const Instance a(shared, glm::translate(Mat4(1.0f), Vec3(-3, 0, 0))),
        b(shared, glm::translate(Mat4(1.0f), Vec3(3, 0, 0)));
    SurfaceHit ha, hb;
    REQUIRE(a.intersect(Ray{{-3, 0.1f, 5}, {0, 0, -1}}, ha));
    REQUIRE(b.intersect(Ray{{3, 0.1f, 5}, {0, 0, -1}}, hb));
    CHECK(ha.shape == &a);
    CHECK(hb.shape == &b);
    CHECK(ha.primitive == hb.primitive);
    CHECK(ha.object_point == hb.object_point);
    CHECK(glm::length(ha.point_error) > 0.0f);
}
