#include "render_worker.hpp"

#include <rtlab/render/render_job.hpp>

#include <catch2/catch.hpp>
#include <scratch_files.hpp>

#include <chrono>
#include <fstream>
#include <thread>

using namespace rtlab;
using namespace rtlab::view;

namespace {

SceneLoadOptions small_whitted() {
    SceneLoadOptions load;
    load.overrides.width = 48;
    load.overrides.height = 36;
    load.overrides.seed = 7;
    load.use_environment = false;
    return load;
}

const std::filesystem::path kScene = std::filesystem::path(RTLAB_SOURCE_DIR) / "scenes" / "whitted.json";

/// Collects events until one of `kind` with `request` (0: any) came, an unexpected error came, or a minute
/// passed (a hung worker fails the test rather than hanging it).
bool wait_for(RenderWorker& worker, WorkerEvent::Kind kind, int pass, std::uint64_t request,
              std::vector<WorkerEvent>* seen = nullptr) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (std::chrono::steady_clock::now() < deadline) {
        for (const WorkerEvent& e : worker.take_events()) {
            if (seen) seen->push_back(e);
            if (e.kind == WorkerEvent::Kind::error && kind != WorkerEvent::Kind::error) {
                UNSCOPED_INFO(e.message);  // fail now, saying why, rather than after a minute
                return false;
            }
            if (e.kind == kind && e.pass == pass && (request == 0 || e.request == request)) return true;
        }
        std::this_thread::yield();
    }
    return false;
}

}  // namespace

TEST_CASE("the viewer's passes add up to rtlab-render's sobol image of the same spp and seed", "[view]") {
    RenderWorker worker(kScene, small_whitted());
    RenderChoice choice;
    choice.spp = 3;
    choice.seed = 7;
    const std::uint64_t request = worker.set_choice(choice);
    REQUIRE(wait_for(worker, WorkerEvent::Kind::pass, 3, request));
    DisplayBuffer pixels;
    const auto rows = worker.take_pixels(pixels);
    REQUIRE(rows.first == 0);
    REQUIRE(rows.second == 36);

    LoadedScene scene = load_scene(kScene, small_whitted());
    scene.job.settings.pattern = PixelPattern::sobol;
    scene.job.settings.spp = 3;
    const RenderResult expected = render_job(scene.job);
    REQUIRE(pixels.width == expected.image.width());
    for (int y = 0; y < pixels.height; ++y)
        for (int x = 0; x < pixels.width; ++x) {
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * 48 + static_cast<std::size_t>(x));
            const RGB want = expected.image.at(x, y);
            REQUIRE(pixels.mean[i] == want.r);
            REQUIRE(pixels.mean[i + 1] == want.g);
            REQUIRE(pixels.mean[i + 2] == want.b);
            REQUIRE(pixels.counts[i / 3] == 3);
        }
}

TEST_CASE("a new camera stops the render and restarts it for the new request", "[view]") {
    RenderWorker worker(kScene, small_whitted());
    RenderChoice choice;
    choice.spp = 1000;  // far more than the test waits for: the restart must cut it short
    worker.set_choice(choice);
    REQUIRE(wait_for(worker, WorkerEvent::Kind::pass, 1, 0));
    CameraSpec spec;
    spec.eye = Point3(0.0f, 3.0f, 5.0f);
    spec.look_at = Point3(0.0f, 1.0f, -2.0f);
    spec.width = 48;
    spec.height = 36;
    const std::uint64_t request = worker.set_camera(std::make_shared<PinholeCamera>(spec));
    std::vector<WorkerEvent> seen;
    REQUIRE(wait_for(worker, WorkerEvent::Kind::pass, 2, request, &seen));
    CHECK(worker.status().request == request);
    CHECK(worker.status().restart_ms > 0.0);
}

TEST_CASE("a broken scene is reported and the last image stays", "[view]") {
    const auto dir = std::filesystem::temp_directory_path() / ("rtlab_view_worker_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto file = dir / "scene.json";
    std::filesystem::copy_file(kScene, file, std::filesystem::copy_options::overwrite_existing);
    RenderWorker worker(file, small_whitted());
    RenderChoice choice;
    choice.spp = 2;
    worker.set_choice(choice);
    REQUIRE(wait_for(worker, WorkerEvent::Kind::pass, 2, 0));
    DisplayBuffer before, after;
    REQUIRE(worker.take_pixels(before).second == 36);
    std::ofstream(file) << "{\"version\": 1, \"camera\": {\"fov\": }}";
    const std::uint64_t request = worker.reload();
    std::vector<WorkerEvent> seen;
    REQUIRE(wait_for(worker, WorkerEvent::Kind::error, 0, request, &seen));
    CHECK_THAT(seen.back().message, Catch::Contains("scene.json:1:"));
    const auto rows = worker.take_pixels(after);
    CHECK(rows.first == rows.second);
    CHECK(worker.scene() != nullptr);
    std::filesystem::remove_all(dir);
}

TEST_CASE("the worker watches the scene file and the files it names", "[view]") {
    const auto dir = std::filesystem::temp_directory_path() / ("rtlab_view_assets_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    write_image(Image(4, 4, RGB(0.2f, 0.4f, 0.6f)), dir / "wall.png");
    const auto file = dir / "scene.json";
    std::ofstream(file) << R"({"version": 1, "camera": {}, "render": {"width": 8, "height": 8},
        "textures": [{"name": "wall", "type": "image", "filename": "wall.png"}],
        "materials": [{"name": "m", "type": "phong", "kd": "wall"}],
        "shapes": [{"type": "sphere", "center": [0, 0, -3], "material": "m"}]})";
    RenderWorker worker(file, small_whitted());
    RenderChoice choice;
    choice.spp = 1;
    worker.set_choice(choice);
    REQUIRE(wait_for(worker, WorkerEvent::Kind::pass, 1, 0));
    const auto files = worker.watched_files();
    REQUIRE(files.size() == 2);
    CHECK(files[0] == file);
    CHECK(std::filesystem::equivalent(files[1], dir / "wall.png"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("photon and sppm in the viewer give rtlab-render's images", "[view]") {
    // sppm runs one iteration per pass and shows the whole image after each; photon is a radiance source like path.
    const std::filesystem::path dir = rtlab::test::scratch_dir("view_photon");
    const std::filesystem::path file = dir / "glass.json";
    std::ofstream(file) << R"({"version": 1,
      "camera": {"position": [0, 1.5, 4], "look_at": [0, 0.4, 0]},
      "render": {"width": 16, "height": 16, "aa": "sobol", "seed": 5, "integrator": "path", "max_depth": 5,
                 "photons": {"count": 3000, "nearest": 20}},
      "materials": [{"name": "floor", "type": "lambert", "albedo": 0.7}, {"name": "glass", "type": "glass"},
                    {"name": "lamp", "type": "lambert", "albedo": 0, "emission": 20}],
      "shapes": [{"type": "quad", "corner": [-3, 0, 3], "edge_u": [6, 0, 0], "edge_v": [0, 0, -6], "material": "floor"},
                 {"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "glass"},
                 {"type": "sphere", "center": [0.5, 2, -0.5], "radius": 0.2, "material": "lamp"}]})";
    SceneLoadOptions load;
    load.use_environment = false;
    for (const char* name : {"photon", "sppm"}) {
        INFO(name);
        RenderWorker worker(file, load);
        RenderChoice choice;
        choice.integrator = name;
        choice.spp = 3;
        const std::uint64_t request = worker.set_choice(choice);
        REQUIRE(wait_for(worker, WorkerEvent::Kind::pass, 3, request));
        DisplayBuffer pixels;
        worker.take_pixels(pixels);
        LoadedScene scene = load_scene(file, load);
        scene.job.integrator = *parse_integrator(name);
        scene.job.settings.spp = 3;
        const RenderResult expected = render_job(scene.job);
        REQUIRE(pixels.width == 16);
        double sum = 0.0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const std::size_t i = 3 * (static_cast<std::size_t>(y) * 16 + static_cast<std::size_t>(x));
                const RGB want = expected.image.at(x, y);
                REQUIRE(pixels.mean[i] == want.r);
                REQUIRE(pixels.mean[i + 1] == want.g);
                REQUIRE(pixels.mean[i + 2] == want.b);
                sum += want.g;
            }
        CHECK(sum > 1.0);
    }
    std::filesystem::remove_all(dir);
}
