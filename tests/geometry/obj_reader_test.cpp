#include <rtlab/core/error.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"

#include <fstream>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
const auto dir = test::scratch_dir("geometry_obj");

std::filesystem::path write_file(const std::string& name, const std::string& content) {
    const auto p = dir / name;
    std::ofstream(p, std::ios::binary) << content;
    return p;
}
}  // namespace

TEST_CASE("OBJ polygons are fanned in file order across groups", "[obj]") {
    const auto path = write_file("groups.obj",
                                 "# two groups\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                                 "g first\nf 1 2 3 4\ng second\nf 1 2 5\nf 2 3\n");
    MeshLoadInfo info;
    const TriangleMesh m = load_mesh(path, &info);
    CHECK(info.format == "obj");
    REQUIRE(m.triangle_count() == 3);  // the 2-corner face is dropped without taking an index
    CHECK(m.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(m.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
    CHECK(m.triangles[2] == std::array<std::uint32_t, 3>{0, 1, 4});
    CHECK(m.vertex_count() == 5);
    CHECK_FALSE(m.has_normals());
}

TEST_CASE("OBJ negative indices, normals and uvs", "[obj]") {
    const auto path = write_file("relative.obj",
                                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                                 "f -3/-3/-1 -2/-2/-1 -1/-1/-1\n");
    const TriangleMesh m = load_obj(path);
    REQUIRE(m.triangle_count() == 1);
    REQUIRE(m.has_normals());
    REQUIRE(m.has_uvs());
    CHECK(m.corner(0, 1) == Point3(1, 0, 0));
    CHECK(m.uvs[m.triangles[0][2]] == Vec2(0, 1));
    CHECK(m.normals[m.triangles[0][0]] == Normal3(0, 0, 1));
}

TEST_CASE("a missing material library is a warning, not a failure", "[obj]") {
    const auto path = write_file("mtl.obj", "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    MeshLoadInfo info;
    const TriangleMesh m = load_obj(path, &info);
    CHECK(m.triangle_count() == 1);
    CHECK_FALSE(info.warnings.empty());
}

TEST_CASE("malformed OBJ files give errors naming the file and the problem", "[obj]") {
    struct Bad {
        const char* name;
        std::string content;
        const char* error;
    };
    const Bad cases[] = {
        {"empty.obj", "", "empty file"},
        {"garbage.obj", "this is not a mesh\nat all\n", "no vertices or faces"},
        {"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "vertex index 4 out of range (3 vertices)"},
        {"nanv.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n", "line 2: vertex coordinate 2"},
        {"infv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n", "line 3: vertex coordinate 3"},
        {"shortv.obj", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: vertex coordinate 3 is missing"},
        {"wordv.obj", "v 0 0 0\nv one 0 0\nv 0 1 0\nf 1 2 3\n", "line 2: vertex coordinate 1"},
        {"zeroindex.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "zeroindex.obj"},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        const auto path = write_file(c.name, c.content);
        CHECK_THROWS_AS(load_obj(path), Error);
        CHECK_THROWS_WITH(load_obj(path), Contains(c.name) && Contains(c.error));
    }
    CHECK_THROWS_WITH(load_obj(dir / "missing.obj"), Contains("missing.obj") && Contains("no such file"));
    CHECK_THROWS_WITH(load_obj(dir), Contains("is a directory"));
}
