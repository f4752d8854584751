#include <rtlab/accel/accelerator.hpp>

#include <catch2/catch.hpp>

#include "test_meshes.hpp"

using namespace rtlab;

TEST_CASE("octree leaves hold at most 10 primitives unless the depth cap stops them", "[octree]") {
    SECTION("a spread-out icosphere splits to small leaves") {
        const TriangleMesh mesh = test::icosphere(4);  // 5120 triangles
        const AccelStats s = make_accelerator("octree", mesh)->stats();
        CHECK(s.leaves > static_cast<std::int64_t>(mesh.triangle_count()) / 10);
        CHECK(s.mean_leaf_primitives > 0.0);
        CHECK(s.mean_leaf_primitives <= 10.0);
        CHECK(s.max_depth >= 3);
        CHECK(s.max_depth <= 10);
        // Eight equal children per interior node: nodes = 1 + 8 * interior nodes.
        CHECK((s.nodes - 1) % 8 == 0);
        CHECK(s.leaves == s.nodes - (s.nodes - 1) / 8);
    }
    SECTION("1000 stacked quads cannot be separated and stay shallow") {
        const TriangleMesh mesh = test::stacked_quads(1000);
        const AccelStats s = make_accelerator("octree", mesh)->stats();
        CHECK(s.max_depth <= 10);
        CHECK(s.bytes > 0);
    }
    SECTION("ten triangles are one leaf") {
        TriangleMesh mesh = test::icosphere(0);
        mesh.triangles.resize(10);
        const AccelStats s = make_accelerator("octree", mesh)->stats();
        CHECK(s.nodes == 1);
        CHECK(s.leaves == 1);
        CHECK(s.mean_leaf_primitives == 10.0);
    }
}
