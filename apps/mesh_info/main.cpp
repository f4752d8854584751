// rtlab-mesh-info FILE...: loads each mesh and prints its format, vertices, triangles, degenerate
// triangles, bounds and load time; a file that cannot be loaded gives its error on stderr and exit status 1.
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <fmt/core.h>

#include <chrono>
#include <exception>

int main(int argc, char** argv) {
    if (argc < 2) {
        fmt::print(stderr,
                   "usage: rtlab-mesh-info FILE...\n  prints format, vertices, triangles, degenerate "
                   "triangles, bounds and load time of each .ply or .obj mesh\n");
        return 2;
    }
    int status = 0;
    for (int i = 1; i < argc; ++i) {
        try {
            rtlab::MeshLoadInfo info;
            const auto start = std::chrono::steady_clock::now();
            const rtlab::TriangleMesh mesh = rtlab::load_mesh(argv[i], &info);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const rtlab::AABB b = mesh.bounds();
            fmt::print("{}\n  format      {}\n  vertices    {}\n  triangles   {}\n  degenerate  {}\n", argv[i],
                       info.format, mesh.vertex_count(), mesh.triangle_count(), mesh.degenerate_count());
            fmt::print("  normals     {}\n  uvs         {}\n", mesh.has_normals() ? "yes" : "no",
                       mesh.has_uvs() ? "yes" : "no");
            if (!b.is_empty())
                fmt::print("  bounds      ({:g} {:g} {:g}) .. ({:g} {:g} {:g}), diagonal {:g}\n", b.lo.x, b.lo.y,
                           b.lo.z, b.hi.x, b.hi.y, b.hi.z, b.diagonal());
            fmt::print("  load time   {:.3f} s\n", seconds);
            for (const auto& w : info.warnings) fmt::print("  warning     {}\n", w);
        } catch (const std::exception& e) {
            fmt::print(stderr, "rtlab-mesh-info: {}\n", e.what());
            status = 1;
        }
    }
    return status;
}
