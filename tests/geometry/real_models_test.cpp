#include <rtlab/geometry/mesh_io.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"

using namespace rtlab;

TEST_CASE("the real models load with their published triangle and vertex counts", "[models]") {
    const auto shared = test::shared_dir();
    if (!shared) {
        WARN("skipped: no shared data folder (set RTLAB_SHARED_DIR to the folder holding models/)");
        return;
    }
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
        if (!std::filesystem::exists(path)) {
            WARN("skipped: " << path << " is absent");
            continue;
        }
        const TriangleMesh mesh = load_mesh(path);
        CHECK(mesh.triangle_count() == m.triangles);
        CHECK(mesh.degenerate_count() == 0);
        CHECK(mesh.bounds().diagonal() == Approx(m.diagonal).epsilon(1e-4));
        if (!mesh.has_normals() && !mesh.has_uvs()) CHECK(mesh.vertex_count() == m.vertices);
        CHECK_NOTHROW(mesh.validate());
    }
}
