#include <rtlab/core/error.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"

#include <bit>
#include <cstring>
#include <fstream>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
struct BadFileCase {
    const char* name;
    std::string content;
    const char* error;
};
}  // namespace

namespace {
const auto dir = test::scratch_dir("geometry_ply");

std::filesystem::path write_file(const std::string& name, const std::string& content) {
    const auto p = dir / name;
    std::ofstream(p, std::ios::binary) << content;
    return p;
}

// Binary writer for PLY bodies in either byte order.
struct Bytes {
    bool big_endian;
    std::string data;
    template <class T>
    Bytes& put(T value) {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        if (big_endian == (std::endian::native == std::endian::little))
            for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
        data.append(raw, sizeof(T));
        return *this;
    }
};

const std::string kSquareAscii =
    "ply\nformat ascii 1.0\ncomment a unit square as one quad\nobj_info made by hand\n"
    "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
}  // namespace

TEST_CASE("ascii PLY with a quad is fanned in place", "[ply]") {
    MeshLoadInfo info;
    const TriangleMesh m = load_mesh(write_file("square.ply", kSquareAscii), &info);
    CHECK(info.format == "ply ascii");
    REQUIRE(m.vertex_count() == 4);
    REQUIRE(m.triangle_count() == 2);
    CHECK(m.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(m.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
}

TEST_CASE("CRLF line ends and extra whitespace are accepted", "[ply]") {
    std::string crlf;
    for (char c : kSquareAscii) {
        if (c == '\n')
            crlf += "\r\n";
        else
            crlf += c;
    }
    const TriangleMesh m = load_ply(write_file("crlf.ply", crlf));
    CHECK(m.triangle_count() == 2);
    CHECK(m.positions[2] == Point3(1, 1, 0));
}

TEST_CASE("binary PLY in both byte orders with any property order and types", "[ply]") {
    for (bool big : {false, true}) {
        // Vertex properties shuffled, with colour and confidence to skip, normals, uvs and a double z.
        std::string header = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                             " 1.0\nelement vertex 3\nproperty uchar red\nproperty double z\nproperty float x\n"
                             "property float confidence\nproperty float y\nproperty float nx\nproperty float ny\n"
                             "property float nz\nproperty float s\nproperty float t\nproperty uchar green\n"
                             "element face 2\nproperty uchar flags\nproperty list ushort uint vertex_index\n"
                             "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
        Bytes b{big, {}};
        const float xs[] = {0, 1, 0}, ys[] = {0, 0, 1};
        const double zs[] = {0.5, 0.5, 0.5};
        for (int i = 0; i < 3; ++i) {
            b.put<std::uint8_t>(200).put<double>(zs[i]).put<float>(xs[i]).put<float>(0.9f).put<float>(ys[i]);
            b.put<float>(0).put<float>(0).put<float>(1).put<float>(xs[i]).put<float>(ys[i]).put<std::uint8_t>(7);
        }
        b.put<std::uint8_t>(1).put<std::uint16_t>(3).put<std::uint32_t>(0).put<std::uint32_t>(1).put<std::uint32_t>(2);
        b.put<std::uint8_t>(1).put<std::uint16_t>(2).put<std::uint32_t>(0).put<std::uint32_t>(1);  // 2 corners: dropped
        b.put<std::int32_t>(0).put<std::int32_t>(1);
        MeshLoadInfo info;
        const TriangleMesh m = load_ply(write_file(big ? "be.ply" : "le.ply", header + b.data), &info);
        CHECK(info.format == (big ? "ply binary_big_endian" : "ply binary_little_endian"));
        CHECK(info.warnings ==
              std::vector<std::string>{"1 face with fewer than 3 corners dropped (element 'face' #1)"});
        REQUIRE(m.vertex_count() == 3);
        REQUIRE(m.triangle_count() == 1);
        CHECK(m.positions[1] == Point3(1, 0, 0.5f));
        REQUIRE(m.has_normals());
        CHECK(m.normals[2] == Normal3(0, 0, 1));
        REQUIRE(m.has_uvs());
        CHECK(m.uvs[2] == Vec2(0, 1));
    }
}

TEST_CASE("PLY faces with fewer than 3 corners are dropped with a warning naming the first", "[ply]") {
    // Line 11 is the first data line; the faces start at line 15.
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 5\nproperty list uchar int vertex_indices\n"
        "property uchar flags\nend_header\n";
    const std::string vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
    MeshLoadInfo info;
    const TriangleMesh m =
        load_mesh(write_file("short.ply", header + vertices + "3 0 1 2 7\n2 0 1 7\n0 7\n4 0 1 2 3 7\n1 3 7\n"), &info);
    REQUIRE(m.triangle_count() == 3);
    CHECK(m.triangles[1] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(m.triangles[2] == std::array<std::uint32_t, 3>{0, 2, 3});
    CHECK(info.warnings ==
          std::vector<std::string>{"3 faces with fewer than 3 corners dropped (line 16: element 'face' #1 and later)"});

    MeshLoadInfo clean;
    CHECK(load_ply(write_file("fine.ply", header + vertices +
                                              "3 0 1 2 7\n3 0 2 3 7\n3 1 2 3 7\n3 0 1 3 7\n"
                                              "3 0 1 2 7\n"),
                   &clean)
              .triangle_count() == 5);
    CHECK(clean.warnings.empty());
}

TEST_CASE("a PLY file left with no triangle is an error", "[ply]") {
    const std::string vertex_header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\n";
    const std::string face_header = "property list uchar int vertex_indices\nend_header\n";
    const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
    const BadFileCase cases[] = {
        {"segment.ply", vertex_header + "element face 1\n" + face_header + vertices + "2 0 1\n",
         "no triangles: 1 face with fewer than 3 corners dropped (line 13: element 'face' #0)"},
        {"segments.ply", vertex_header + "element face 2\n" + face_header + vertices + "2 0 1\n0\n",
         "no triangles: 2 faces with fewer than 3 corners dropped (line 13: element 'face' #0 and later)"},
        {"nofaces.ply", vertex_header + "element face 0\n" + face_header + vertices, "no faces"},
        {"points.ply", vertex_header + "end_header\n" + vertices, "no faces"},
        {"segmentbin.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" +
             std::string(24, '\0') + std::string("\x02\x00\x00\x00\x00\x01\x00\x00\x00", 9),
         "no triangles: 1 face with fewer than 3 corners dropped (element 'face' #0)"},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        const auto path = write_file(c.name, c.content);
        CHECK_THROWS_AS(load_ply(path), Error);
        CHECK_THROWS_WITH(load_mesh(path), Contains(c.name) && Contains(c.error));
    }
}

namespace {
struct BadFile {
    const char* name;
    std::string content;
    const char* error;
};

std::string binary_vertices_header(int vertices, int faces) {
    return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
           "\nproperty list uchar int vertex_indices\nend_header\n";
}
}  // namespace

TEST_CASE("malformed PLY files give errors naming the file and the problem", "[ply]") {
    const std::string good_vertices = "0 0 0\n1 0 0\n0 1 0\n";
    const std::string header3 =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const BadFile cases[] = {
        {"empty.ply", "", "empty file"},
        {"magic.ply", "plx\nformat ascii 1.0\nend_header\n", "not a PLY file"},
        {"noformat.ply", "ply\nelement vertex 0\nproperty float x\nend_header\n", "no format line"},
        {"badformat.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", "line 2: unknown format"},
        {"noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "before 'end_header'"},
        {"badtype.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
         "line 4: unknown property type"},
        {"keyword.ply", "ply\nformat ascii 1.0\nelephant vertex 1\nend_header\n", "line 3: unknown header keyword"},
        {"negcount.ply", "ply\nformat ascii 1.0\nelement vertex -3\nproperty float x\nend_header\n",
         "invalid count '-3'"},
        {"orphan.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n", "property before any element"},
        {"noxyz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
         "lacks x, y or z"},
        {"novertex.ply", "ply\nformat ascii 1.0\nelement thing 0\nproperty float x\nend_header\n",
         "no 'vertex' element"},
        {"nolist.ply",
         "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 0\nproperty int vertex_indices\nend_header\n",
         "no 'vertex_indices' list"},
        {"floatcount.ply",
         "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 0\nproperty list float int vertex_indices\nend_header\n",
         "list count type"},
        {"absurd.ply",
         "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\nproperty float "
         "z\nend_header\n0 0 0\n",
         "more than the"},
        {"absurdbin.ply", binary_vertices_header(1000000, 0) + std::string(24, '\0'),
         "header claims 1000000 'vertex' elements"},
        {"shortascii.ply", header3 + "0 0 0\n1 0 0\n", "header claims 3 'vertex' elements, more than the 12 bytes"},
        {"truncascii.ply", header3 + "0 0 0\n1 0 0\n0            \n", "truncated data in element 'vertex' #2"},
        {"truncbin.ply", binary_vertices_header(1, 1) + std::string(12, '\0') + std::string("\x03\x00\x00", 3),
         "truncated data in element 'face' #0"},
        {"badnumber.ply", header3 + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n",
         "line 11: element 'vertex' #1: bad number 'zero'"},
        {"nan.ply", header3 + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "element 'vertex' #1: non-finite vertex coordinate"},
        {"inf.ply", header3 + "0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n", "non-finite vertex coordinate"},
        {"range.ply", header3 + good_vertices + "3 0 1 3\n",
         "element 'face' #0: vertex index 3 out of range (3 vertices)"},
        {"negindex.ply", header3 + good_vertices + "3 0 -1 2\n", "vertex index -1 out of range"},
        {"neglist.ply", header3 + good_vertices + "-3 0 1 2\n", "invalid list length"},
        {"fractional.ply", header3 + good_vertices + "3 0 1.5 2\n", "out of range"},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        const auto path = write_file(c.name, c.content);
        CHECK_THROWS_AS(load_ply(path), Error);
        CHECK_THROWS_WITH(load_ply(path), Contains(c.name) && Contains(c.error));
    }
    CHECK_THROWS_WITH(load_ply(dir / "does_not_exist.ply"), Contains("does_not_exist.ply"));
    CHECK_THROWS_WITH(load_ply(dir), Contains("is a directory"));
    CHECK_THROWS_WITH(load_mesh(write_file("mesh.stl", "solid")), Contains("unknown mesh format '.stl'"));
}
