// rtlab-bunny [--mesh FILE] [--material diffuse|phong|mirror|glass] [common flags]: a mesh (the Stanford bunny
// by default) on a floor, through its kd-tree (apps/bunny/scene.cpp).
#include "scene.hpp"

#include <rtlab/app/course_app.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <fmt/core.h>

#include <chrono>

int main(int argc, char** argv) {
    rtlab::app::CommandLine cli("rtlab-bunny", "rtlab-bunny: the Stanford bunny (or any PLY/OBJ mesh) on a floor");
    rtlab::app::CourseOptions options;
    options.output = "bunny.png";
    options.width = 640;
    options.height = 480;
    rtlab::app::add_course_options(cli, options);
    std::string mesh_name = rtlab::bunny::kDefaultMesh, material = "diffuse";
    cli.add_text("--mesh", mesh_name, "PLY or OBJ file: as given, else on the data path (default " + mesh_name + ")");
    cli.add_word("--material", material, rtlab::bunny::material_names(), "the bunny's material");
    if (const auto status = cli.parse(argc, argv)) return *status;
    return rtlab::app::run_program(cli.program(), [&] {
        rtlab::app::prepare_output(options.output);
        const rtlab::DataPath data =
            rtlab::app::course_data_path(options, rtlab::app::executable_path(argv[0]), "rtlab-bunny");
        // A mesh named by a path that exists is taken as it is; else the name is looked up on the data path.
        const rtlab::DataFile file = std::filesystem::is_regular_file(mesh_name)
                                         ? rtlab::DataFile{mesh_name, "as given", {}}
                                         : data.require(mesh_name);
        const std::filesystem::path& path = file.path;
        if (!options.quiet) fmt::print("{}\n", rtlab::describe_sources({{mesh_name, file}}));
        using Clock = std::chrono::steady_clock;
        auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
        std::shared_ptr<const rtlab::TriangleMesh> mesh;
        rtlab::RenderJob job;
        rtlab::MeshLoadInfo info;
        double read_s = 0.0, normals_s = 0.0, tree_s = 0.0;
        rtlab::app::run_with_threads(options.threads_or_all(), [&] {
            auto t = Clock::now();
            rtlab::TriangleMesh loaded = rtlab::load_mesh(path, &info);
            read_s = since(t);
            t = Clock::now();
            mesh = std::make_shared<const rtlab::TriangleMesh>(rtlab::with_smooth_normals(std::move(loaded)));
            normals_s = since(t);
            t = Clock::now();
            job = rtlab::bunny::make_bunny_job(mesh, material, *options.width, *options.height);
            tree_s = since(t);
        });
        for (const auto& w : info.warnings) fmt::print(stderr, "rtlab-bunny: warning: {}: {}\n", path.string(), w);
        if (!options.quiet)
            fmt::print("{}: {} triangles, read in {:.2f} s, smooth normals {:.2f} s, kd-tree {:.2f} s\n", path.string(),
                       mesh->triangle_count(), read_s, normals_s, tree_s);
        rtlab::app::apply_course_options(options, job);
        return rtlab::app::run_course_render(job, options, options.output, "bunny (" + material + ")").interrupted
                   ? rtlab::app::kExitInterrupted
                   : rtlab::app::kExitDone;
    });
}
