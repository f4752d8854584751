#include <rtlab/core/error.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "shared_data.hpp"

#include <fstream>
#include <span>
#include <string>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
const auto dir = test::scratch_dir("geometry_obj");

std::filesystem::path write_file(const std::string& name, const std::string& content) {
    const auto p = dir / name;
    std::ofstream(p, std::ios::binary) << content;
    return p;
}

// A file the reader must reject: its name, its content, and what its error says besides the file's name.
struct Rejected {
    const char* name;
    std::string content;
    const char* error;
};

// Writes each file and loads it: an Error naming the file and saying what the case expects.
void check_rejected(std::span<const Rejected> cases) {
    for (const Rejected& c : cases) {
        INFO(c.name);
        const auto path = write_file(c.name, c.content);
        CHECK_THROWS_AS(load_obj(path), Error);
        CHECK_THROWS_WITH(load_obj(path), Contains(c.name) && Contains(c.error));
    }
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
    // Dropped, but not silently: the caller hears of it.
    CHECK(std::find(info.warnings.begin(), info.warnings.end(), "1 face with fewer than 3 corners dropped (line 11)") !=
          info.warnings.end());
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
    const Rejected cases[] = {
        {"empty.obj", "", "empty file"},
        {"garbage.obj", "this is not a mesh\nat all\n", "no vertices or faces"},
        {"points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no faces"},
        {"segment.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "no triangles: 1 face with fewer than 3 corners dropped"},
        {"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "vertex index 4 out of range (3 vertices)"},
        {"nanv.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n", "line 2: vertex coordinate 2"},
        {"infv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n", "line 3: vertex coordinate 3"},
        {"shortv.obj", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: vertex coordinate 3 is missing"},
        {"wordv.obj", "v 0 0 0\nv one 0 0\nv 0 1 0\nf 1 2 3\n", "line 2: vertex coordinate 1"},
    };
    check_rejected(cases);
    CHECK_THROWS_WITH(load_obj(dir / "missing.obj"), Contains("missing.obj") && Contains("no such file"));
    CHECK_THROWS_WITH(load_obj(dir), Contains("is a directory"));
}

namespace {
const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
const std::string kTriangleUvNormal = kTriangle + "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n";
}  // namespace

TEST_CASE("OBJ face indices that do not name a vertex are errors naming the file and the line", "[obj]") {
    // tinyobjloader reads indices with atoi: 20 digits wrap to -1 (the last vertex), 4294967299 wraps to 3.
    const Rejected cases[] = {
        {"huge.obj", kTriangle + "f 1 2 12345678901234567890\n",
         "line 4: vertex index 12345678901234567890 out of range"},
        {"wrap.obj", kTriangle + "f 1 2 4294967299\n", "line 4: vertex index 4294967299 out of range (3 vertices)"},
        {"hugeneg.obj", kTriangle + "f 1 2 -12345678901234567890\n", "line 4: vertex index -12345678901234567890"},
        {"zero.obj", kTriangle + "f 0 1 2\n", "line 4: vertex index 0"},
        {"beyond.obj", kTriangle + "# a comment\n\nf 1 2 4\n", "line 6: vertex index 4 out of range (3 vertices)"},
        {"before.obj", kTriangle + "f -1 -2 -4\n", "line 4: vertex index -4 reaches before the first vertex"},
        // Relative to the vertices read so far: two at line 3, though the file has three.
        {"early.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", "line 3: vertex index -3 reaches before the first"},
        {"garbage.obj", kTriangleUvNormal + "f 1/2/x 2/2/1 3/3/1\n", "line 8: face corner '1/2/x' is malformed"},
        {"letters.obj", kTriangle + "f 1 2 x\n", "line 4: face corner 'x' is malformed"},
        {"suffix.obj", kTriangle + "f 1 2 3x\n", "line 4: face corner '3x' is malformed"},
        {"decimal.obj", kTriangle + "f 1 2 3.0\n", "line 4: face corner '3.0' is malformed"},
        {"slash.obj", kTriangle + "f 1/ 2 3\n", "line 4: face corner '1/' is malformed"},
        {"emptyvn.obj", kTriangle + "f 1// 2 3\n", "line 4: face corner '1//' is malformed"},
        {"fourslots.obj", kTriangleUvNormal + "f 1/1/1/1 2/2/1 3/3/1\n", "line 8: face corner '1/1/1/1' is malformed"},
        {"minus.obj", kTriangle + "f 1 2 -\n", "line 4: face corner '-' is malformed"},
        {"uvrange.obj", kTriangleUvNormal + "f 1/4/1 2/2/1 3/3/1\n",
         "line 8: texture coordinate index 4 out of range (3 texture coordinates)"},
        {"uvhuge.obj", kTriangleUvNormal + "f 1/99999999999/1 2/2/1 3/3/1\n",
         "line 8: texture coordinate index 99999999999 out of range"},
        {"normalzero.obj", kTriangleUvNormal + "f 1//0 2//1 3//1\n", "line 8: normal index 0"},
        {"normalneg.obj", kTriangleUvNormal + "f 1//-2 2//1 3//1\n",
         "line 8: normal index -2 reaches before the first"},
        // Line numbers count old Mac (CR) and DOS (CRLF) line ends as tinyobjloader does.
        {"cr.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 5\r", "line 4: vertex index 5 out of range"},
        {"crlf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 5\r\n", "line 4: vertex index 5 out of range"},
        {"crvertex.obj", "v 0 0 0\rv 1 nan 0\rv 0 1 0\rf 1 2 3\r", "line 2: vertex coordinate 2"},
        {"indented.obj", "v 0 0 0\n  v 1 nan 0\nv 0 1 0\n\tf 1 2 3\n", "line 2: vertex coordinate 2"},
        {"indentedf.obj", kTriangle + "  \tf 1 2 0\n", "line 4: vertex index 0"},
    };
    int rejected = 0;
    for (const auto& c : cases) {
        INFO(c.name);
        const auto path = write_file(c.name, c.content);
        CHECK_THROWS_WITH(load_obj(path), Contains(c.name) && Contains(c.error));
        try {
            load_obj(path);
        } catch (const Error&) {
            ++rejected;
        }
    }
    CHECK(rejected == static_cast<int>(std::size(cases)));
}

TEST_CASE("OBJ faces may name vertices defined later in the file", "[obj]") {
    // The loader checks a file in one pass: a positive index beyond the vertices read so far is settled against
    // the file's totals at its end.
    const auto path = write_file("forward.obj",
                                 "f 1 2 3\nf 1/1 3/3 4/2\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                 "vt 0 0\nvt 1 0\nvt 0 1\n");
    const TriangleMesh m = load_obj(path);
    REQUIRE(m.triangle_count() == 2);
    CHECK(m.corner(0, 1) == Point3(1, 0, 0));
    CHECK(m.corner(1, 2) == Point3(1, 1, 0));
}

TEST_CASE("OBJ errors name the first bad line when a forward index comes before another error", "[obj]") {
    const Rejected cases[] = {
        // Index 5 at line 1 is out of range for the file's 4 vertices: that is the first error, not line 3.
        {"fwdfirst.obj", "f 1 2 5\nv 0 0 0\nv 1 nan 0\nv 0 1 0\nv 1 1 0\n",
         "line 1: vertex index 5 out of range (4 vertices)"},
        // Index 4 at line 1 is legal (4 vertices in all): the error is line 3's.
        {"fwdlegal.obj", "f 1 2 4\nv 0 0 0\nv 1 nan 0\nv 0 1 0\nv 1 1 0\n", "line 3: vertex coordinate 2"},
        // On one line, the corner first in the line decides: index 9 before the malformed corner.
        {"fwdsameline.obj", kTriangle + "f 1 9 x\n", "line 4: vertex index 9 out of range (3 vertices)"},
        {"fwduv.obj", "f 1/4 2/1 3/1\n" + kTriangle + "vt 0 0\nvt 1 0\nf 1 2 0\n",
         "line 1: texture coordinate index 4 out of range (2 texture coordinates)"},
        // Counted to the file's end, past the line with the other error.
        {"fwdlater.obj", "f 1 2 4\nv 0 0 0\nv 1 0 0\nf 1 2 0\nv 0 1 0\nv 1 1 0\n", "line 4: vertex index 0"},
    };
    check_rejected(cases);
}

TEST_CASE("OBJ face corners in every legal form still load", "[obj]") {
    // v, v/vt, v//vn, v/vt/vn, positive and relative, '+' signs, tabs, CRLF and trailing blanks.
    const auto path = write_file("forms.obj", kTriangleUvNormal +
                                                  "v 1 1 0\n"
                                                  "f 1 2 3\n"
                                                  "f 1/1 2/2 3/3\n"
                                                  "f\t1//1\t2//1  3//1 \r\n"
                                                  "f 1/1/1 +2/2/1 -2/-1/-1\n"
                                                  "f -4 -3 -1 \n");
    const TriangleMesh m = load_obj(path);
    REQUIRE(m.triangle_count() == 5);
    CHECK(m.corner(3, 2) == Point3(0, 1, 0));  // -2 of four vertices
    CHECK(m.corner(4, 2) == Point3(1, 1, 0));
}

TEST_CASE("OBJ numbers the quick line check settles alone agree with the full check", "[obj]") {
    // Plain decimals and unsigned in-range corners skip from_chars; everything else (exponents, a bare point, ten
    // digits, leading zeros, empty slots) goes the general way, and both must judge alike.
    const auto path = write_file("quick.obj",
                                 "v 1. .5 +.5\n"
                                 "v -0 1e-5 +2.25\n"
                                 "v 0000000000000000000000000000000000000000001.5 0 1\n"
                                 "vt 0 0\nvn 0 0 1\n"
                                 "f 01 2 0000000003\n"
                                 "f 1/1/1 2/1/1 3/1/1\n"
                                 "f 1//1 2//1 3//01\n");
    const TriangleMesh m = load_obj(path);
    REQUIRE(m.triangle_count() == 3);
    CHECK(m.corner(0, 0) == Point3(1.0f, 0.5f, 0.5f));
    CHECK(m.corner(0, 1) == Point3(-0.0f, 1e-5f, 2.25f));
    CHECK(m.corner(0, 2) == Point3(1.5f, 0.0f, 1.0f));

    const Rejected cases[] = {
        {"quickhuge.obj", "v 1e400 0 0\n" + kTriangle + "f 2 3 4\n", "line 1: vertex coordinate 1"},
        {"quickhex.obj", "v 0x1 0 0\n" + kTriangle + "f 2 3 4\n", "line 1: vertex coordinate 1"},
        {"quickpoint.obj", "v 0 . 0\n" + kTriangle + "f 2 3 4\n", "line 1: vertex coordinate 2"},
        {"quicksign.obj", "v 0 0 -\n" + kTriangle + "f 2 3 4\n", "line 1: vertex coordinate 3"},
        {"quickemptyvn.obj", kTriangleUvNormal + "f 1/1/ 2/1/1 3/1/1\n", "line 8: face corner '1/1/' is malformed"},
        {"quickzero.obj", kTriangleUvNormal + "f 1/1/1 2/0/1 3/1/1\n", "line 8: texture coordinate index 0"},
        {"quicknormal.obj", kTriangleUvNormal + "f 1//1 2//2 3//1\n",
         "line 8: normal index 2 out of range (1 normals)"},
        {"quickten.obj", kTriangle + "f 1 2 0000000004\n", "line 4: vertex index 0000000004 out of range"},
    };
    check_rejected(cases);
}

TEST_CASE("OBJ polygons in every corner form fan in order and share de-indexed corners", "[obj]") {
    // A pentagon of v/vt/vn corners, relative indices in the second face: five corners fan into three triangles
    // (c0 c1 c2) (c0 c2 c3) (c0 c3 c4); a corner repeated with the same indices is one vertex.
    const auto path = write_file("pentagon.obj",
                                 "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\n"
                                 "vt 0 0\nvt 1 0\nvn 0 0 1\nvn 0 0 -1\n"
                                 "f 1/1/1 2/2/1 3/1/1 4/2/1 5/1/1\n"
                                 "f -5/-2/-2 -3/-2/-2 -1/-1/-1\n");
    const TriangleMesh m = load_obj(path);
    REQUIRE(m.triangle_count() == 4);
    CHECK(m.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(m.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
    CHECK(m.triangles[2] == std::array<std::uint32_t, 3>{0, 3, 4});
    CHECK(m.triangles[3] == std::array<std::uint32_t, 3>{0, 2, 5});  // 5/2/2 is new, the others repeat
    REQUIRE(m.vertex_count() == 6);
    CHECK(m.positions[5] == Point3(0, 1, 0));
    CHECK(m.normals[5] == Normal3(0, 0, -1));
    CHECK(m.uvs[5] == Vec2(1, 0));
}

TEST_CASE("OBJ line ends: CRLF and a last line without a newline read alike", "[obj]") {
    const std::string lf = "v 0 0 0.5\nv 1.25 0 0\nv 0 1 -2\nf 1 2 3";
    std::string crlf;
    for (const char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    for (const auto& [name, content] :
         {std::pair{"eof.obj", lf}, std::pair{"eofcrlf.obj", crlf + "\r\n"}, std::pair{"eofcr.obj", crlf}}) {
        INFO(name);
        const TriangleMesh m = load_obj(write_file(name, content));
        REQUIRE(m.triangle_count() == 1);
        CHECK(m.positions[0] == Point3(0, 0, 0.5f));
        CHECK(m.positions[1] == Point3(1.25f, 0, 0));
        CHECK(m.positions[2] == Point3(0, 1, -2));
    }
    // A vertex on the last line, named by a face before it, without a newline.
    const TriangleMesh m = load_obj(write_file("eofvertex.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 7"));
    REQUIRE(m.triangle_count() == 1);
    CHECK(m.positions[2] == Point3(0, 1, 7));
}

TEST_CASE("OBJ numbers keep the bits the meshes were read with before", "[obj]") {
    // Read as tinyobjloader read them (kept so that images of existing meshes stay byte-identical): digit by digit
    // in a double, exponents through pow(5, e) and ldexp; numbers like these come out as the nearest floats.
    const auto path = write_file("numbers.obj",
                                 "v -0.037830 0.127940 0.004475\n"
                                 "v 1e2 -2.5E-1 +.75\n"
                                 "v 3. -0 12345678\n"
                                 "f 1 2 3\n");
    const TriangleMesh m = load_obj(path);
    REQUIRE(m.vertex_count() == 3);
    CHECK(m.positions[0] == Point3(-0.037830f, 0.127940f, 0.004475f));
    CHECK(m.positions[1] == Point3(100.0f, -0.25f, 0.75f));
    CHECK(m.positions[2] == Point3(3.0f, 0.0f, 12345678.0f));
    CHECK(std::signbit(m.positions[2].y));
}

TEST_CASE("OBJ bad numbers and huge input give errors or bounded reads", "[obj]") {
    const std::string digits400(400, '9');
    static constexpr char kNul[] = "v 0 0 0\nv 1 0 0\nv 0 1\0 0\nf 1 2 3\n";
    const Rejected cases[] = {
        // Finite as a double, infinite as the float a vertex keeps.
        {"floatrange.obj", "v 0 0 0\nv 1 1e39 0\nv 0 1 0\nf 1 2 3\n", "line 2: vertex coordinate 2 is beyond"},
        {"digits.obj", "v " + digits400 + " 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: vertex coordinate 1"},
        {"twodots.obj", "v 1..5 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: vertex coordinate 1"},
        {"bareexp.obj", "v 1.5e 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: vertex coordinate 1"},
        {"hugeexp.obj", "v 1e2147483648 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: vertex coordinate 1"},
        {"intmax.obj", kTriangle + "f 1 2 2147483648\n", "line 4: vertex index 2147483648 out of range (3 vertices)"},
        {"negintmax.obj", kTriangle + "f 1 2 -2147483649\n", "line 4: vertex index -2147483649 reaches before"},
        // Cut at the NUL, as tinyobjloader's C strings were.
        {"nul.obj", std::string(kNul, sizeof kNul - 1), "line 3: vertex coordinate 3"},
    };
    check_rejected(cases);

    // One face of 100000 corners fans into 99998 triangles; a megabyte of blanks is one empty line.
    std::string big = kTriangle + "f";
    for (int i = 0; i < 100000; ++i) big += i % 3 == 0 ? " 1" : i % 3 == 1 ? " 2" : " 3";
    big += "\n" + std::string(1 << 20, ' ') + "\n";
    CHECK(load_obj(write_file("bigface.obj", big)).triangle_count() == 99998);

    // Malformed vt and vn numbers read as 0, as they always did; unknown statements are skipped.
    const TriangleMesh m =
        load_obj(write_file("lenient.obj", kTriangle + "vt x 1\nvt 0.5\nvt 1 1\nvn nan 0 1\n"
                                                       "g part\no thing\ns 1\nl 1 2\np 3\nusemtl none\n"
                                                       "f 1/1/1 2/2/1 3/3/1\n"));
    REQUIRE(m.has_uvs());
    REQUIRE(m.has_normals());
    CHECK(m.uvs[0] == Vec2(0, 1));
    CHECK(m.uvs[1] == Vec2(0.5f, 0));
    CHECK(m.normals[0] == Normal3(0, 0, 1));
}
