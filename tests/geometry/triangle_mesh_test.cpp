#include <rtlab/core/error.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <catch2/catch.hpp>

#include "test_meshes.hpp"

using namespace rtlab;

TEST_CASE("mesh statistics", "[mesh]") {
    const TriangleMesh s = test::icosphere(1);
    CHECK(s.triangle_count() == 80);
    CHECK(s.vertex_count() == 42);
    CHECK(s.degenerate_count() == 0);
    CHECK(s.bounds().lo.x == Approx(-1.0f));
    CHECK(s.bounds().hi.z == Approx(1.0f));
    CHECK_NOTHROW(s.validate());
}

TEST_CASE("degenerate triangles are counted", "[mesh]") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, std::numeric_limits<float>::infinity()}};
    m.triangles = {{0, 1, 3}, {0, 1, 2}, {0, 0, 3}, {0, 1, 4}, {3, 3, 3}};
    CHECK(m.is_degenerate(0) == false);
    CHECK(m.is_degenerate(1));  // collinear
    CHECK(m.is_degenerate(2));  // repeated corner
    CHECK(m.is_degenerate(3));  // infinite corner
    CHECK(m.degenerate_count() == 4);
    // A tiny but real triangle is not degenerate.
    m.positions.push_back({1e-20f, 0, 0});
    m.positions.push_back({0, 1e-20f, 0});
    m.triangles.push_back({0, 5, 6});
    CHECK_FALSE(m.is_degenerate(5));
}

TEST_CASE("validate reports out-of-range indices and mismatched arrays", "[mesh]") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 3}};
    CHECK_THROWS_WITH(m.validate(), Catch::Matchers::Contains("triangle 0: vertex index 3 out of range"));
    m.triangles = {{0, 1, 2}};
    m.normals = {{0, 0, 1}};
    CHECK_THROWS_WITH(m.validate(), Catch::Matchers::Contains("1 normals for 3 positions"));
}
