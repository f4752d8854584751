#include <rtlab/geometry/mesh_io.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"
#include "skip.hpp"

using namespace rtlab;

TEST_CASE("the real models load with their published triangle and vertex counts", "[models]") {
    const auto shared = test::shared_dir();
    if (!shared) return test::skip(test::needs_shared("the models"));
    struct Model {
        const char* file;
        std::size_t triangles, vertices;
        float diagonal;
    };
    // Counts and bounding-box diagonals from models/README.md.
    const Model models[] = {{"stanford-bunny.obj", 69451, 35947, 0.250247f},
                            {"teapot.obj", 6320, 3644, 8.20481f},
                            {"dragon_vrip_res2.ply", 202520, 100250, 0.266607f},
                            {"armadillo.obj", 86482, 43243, 1.51164f},
                            {"buddha.obj", 100000, 49950, 2.28981f}};
    for (const auto& m : models) {
        const auto path = *shared / "models" / m.file;
        INFO(path.string());
        REQUIRE(std::filesystem::exists(path));  // ../shared holds all five (models/README.md)
        const TriangleMesh mesh = load_mesh(path);
        CHECK(mesh.triangle_count() == m.triangles);
        CHECK(mesh.degenerate_count() == 0);
        CHECK(mesh.bounds().diagonal() == Approx(m.diagonal).epsilon(1e-4));
        if (!mesh.has_normals() && !mesh.has_uvs()) CHECK(mesh.vertex_count() == m.vertices);
        CHECK_NOTHROW(mesh.validate());
    }
}

TEST_CASE("the package bunny loads with the triangle count the data manifest gives", "[models]") {
    // glmark2-data's bunny: the Stanford scan with its holes filled, scaled to [-1, 1] (data/assets.tsv).
    int checked = 0;
    for (const AssetEntry& e : asset_manifest()) {
        if (!e.from_package() || e.expected.find(" triangles") == std::string::npos) continue;
        if (!std::filesystem::is_regular_file(e.file)) continue;
        INFO(e.file.string());
        const TriangleMesh mesh = load_mesh(e.file);
        CHECK(std::to_string(mesh.triangle_count()) + " triangles" == e.expected);
        CHECK(mesh.degenerate_count() == 0);
        CHECK_NOTHROW(mesh.validate());
        if (e.name == "models/stanford-bunny.obj") {
            CHECK(mesh.vertex_count() == 34835);
            CHECK(mesh.bounds().hi.x == Approx(1.0f));  // scaled so that its largest extent spans [-1, 1]
            CHECK(mesh.bounds().lo.x == Approx(-1.0f));
        }
        ++checked;
    }
    if (checked == 0) return test::skip("glmark2-data is not installed (scripts/setup.sh)");
}
