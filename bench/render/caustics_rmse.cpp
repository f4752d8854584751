// Caustics (scenes/caustics.json): RMSE against one unbiased converged reference (the path tracer at --ref-spp
// samples per pixel, cached in --reference FILE.pfm when given) against render time, for path (4 to 1024 spp),
// photon (photon counts and spp growing together) and sppm (iterations of --photons photons, measured as it goes).
// Time is CPU time of the process (user + system, over every thread), so that a shared machine's other load does not
// enter it; wall seconds are written too. CSV: method, parameter, cpu_seconds, wall_seconds, rmse, reference_rmse (the
// reference's own error, from its two interleaved half-images: what RMSE can be measured down to).
//   rtlab_render_caustics_rmse [--width N] [--height N] [--ref-spp N] [--max-spp N] [--iterations N] [--photons N]
//                              [--threads N] [--csv FILE] [--reference FILE.pfm] [--data-dir DIR]
#include "image_compare.hpp"

#include <rtlab/core/data_path.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sampled_lights.hpp>
#include <rtlab/render/sppm.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <CLI/CLI.hpp>

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
    return s(u.ru_utime) + s(u.ru_stime);
}

struct Clock {
    double cpu = cpu_seconds();
    std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
    std::pair<double, double> elapsed() const {
        return {cpu_seconds() - cpu, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count()};
    }
};

}  // namespace

int main(int argc, char** argv) {
    const fs::path scene_file = fs::path(RTLAB_SOURCE_DIR) / "scenes/caustics.json";
    std::string csv, reference_file;
    std::vector<fs::path> data_dirs;
    int width = 96, height = 72, ref_spp = 16384, max_spp = 1024, iterations = 512, threads = 2;
    std::uint32_t photons = 50000;
    CLI::App app{"caustics_rmse: RMSE against time of path, photon and sppm on scenes/caustics.json"};
    app.add_option("--width", width, "image width")->check(CLI::Range(8, 1 << 14));
    app.add_option("--height", height, "image height")->check(CLI::Range(8, 1 << 14));
    app.add_option("--ref-spp", ref_spp, "samples per pixel of the path-traced reference")->check(CLI::PositiveNumber);
    app.add_option("--max-spp", max_spp, "path tracer's largest sample count")->check(CLI::Range(4, 1 << 24));
    app.add_option("--iterations", iterations, "sppm's largest iteration count")->check(CLI::PositiveNumber);
    app.add_option("--photons", photons, "photons per map or per sppm iteration")->check(CLI::PositiveNumber);
    app.add_option("--threads", threads, "render threads (0: every core)")->check(CLI::NonNegativeNumber);
    app.add_option("--csv", csv, "write the results as CSV");
    app.add_option("--reference", reference_file, "reference image: read if it exists, else rendered and written");
    app.add_option("--data-dir", data_dirs, "data directory (repeatable)");
    CLI11_PARSE(app, argc, argv);
    SceneLoadOptions load;
    load.data_path = DataPath::from_environment(data_dirs, fs::path(argv[0]));
    load.overrides.width = width;
    load.overrides.height = height;
    LoadedScene scene = load_scene(scene_file, load);
    if (!scene.assets.empty()) std::fprintf(stderr, "%s\n", describe_sources(scene.assets).c_str());
    RenderJob job = scene.job;
    job.settings.threads = threads;
    job.settings.pattern = PixelPattern::sobol;

    Image reference;
    double reference_rmse = -1.0;  // unknown for a cached reference without its .noise file
    if (!reference_file.empty() && fs::exists(reference_file)) {
        reference = read_image(reference_file, ColorEncoding::linear);
        std::fprintf(stderr, "reference: %s\n", reference_file.c_str());
        if (std::FILE* f = std::fopen((reference_file + ".noise").c_str(), "r")) {
            if (std::fscanf(f, "%lf", &reference_rmse) != 1) reference_rmse = -1.0;
            std::fclose(f);
        }
    }
    if (reference.width() != width || reference.height() != height) {
        RenderJob ref = job;
        ref.integrator = IntegratorKind::path;
        ref.settings.spp = ref_spp;
        ref.settings.seed = 1000;
        const Clock clock;
        const RenderResult r = render_job(ref);
        reference = r.image;
        const auto [cpu, wall] = clock.elapsed();
        // Its own error: the two interleaved half-images are each twice as noisy as the whole, and independent.
        reference_rmse = 0.5 * bench::rmse(r.buffer->half_mean_image(0), r.buffer->half_mean_image(1));
        std::fprintf(stderr, "reference: path, %d spp, %.0f s CPU, %.0f s wall; its own RMSE about %.3g\n", ref_spp,
                     cpu, wall, reference_rmse);
        if (!reference_file.empty()) {
            write_image(reference, reference_file);
            if (std::FILE* f = std::fopen((reference_file + ".noise").c_str(), "w"))
                std::fprintf(f, "%.6g\n", reference_rmse), std::fclose(f);
        }
    }

    std::FILE* out = csv.empty() ? stdout : std::fopen(csv.c_str(), "w");
    if (!out) {
        std::fprintf(stderr, "caustics_rmse: cannot write %s\n", csv.c_str());
        return 1;
    }
    std::fprintf(out, "method,parameter,cpu_seconds,wall_seconds,rmse,reference_rmse\n");
    auto row = [&](const char* method, const std::string& parameter, std::pair<double, double> t, const Image& image) {
        std::fprintf(out, "%s,%s,%.3f,%.3f,%.5g,%.4g\n", method, parameter.c_str(), t.first, t.second,
                     bench::rmse(image, reference), reference_rmse);
        std::fflush(out);
    };
    for (int spp = 4; spp <= max_spp; spp *= 4) {
        RenderJob j = job;
        j.integrator = IntegratorKind::path;
        j.settings.spp = spp;
        const Clock clock;
        const Image image = render_job(j).image;
        row("path", std::to_string(spp) + " spp", clock.elapsed(), image);
    }
    // Photon mapping: photons and samples per pixel grow together (4x photons, 2x spp a step), so that both the map's
    // bias and the camera samples' noise fall.
    for (int step = 0, spp = 4; step < 5; ++step, spp *= 2) {
        RenderJob j = job;
        j.integrator = IntegratorKind::photon;
        j.photons.photons = 25000u << (2 * step);
        j.settings.spp = spp;
        const Clock clock;
        const Image image = render_job(j).image;
        row("photon", std::to_string(j.photons.photons) + " photons " + std::to_string(spp) + " spp", clock.elapsed(),
            image);
    }
    {
        const SampledLights sampled = make_sampled_lights(job.scene, job.lights, job.whitted);
        ProgressiveSettings settings;
        settings.seed = 1;
        settings.threads = threads;
        PhotonOptions options = job.photons;
        options.photons = photons;
        const Clock clock;
        SppmRenderer sppm(*job.camera, *sampled.scene, sampled.lights, sampled.sphere, job.path, options, settings);
        for (int next = 1; next <= iterations; next *= 2) {
            while (sppm.iterations() < next) sppm.iterate();
            row("sppm", std::to_string(next) + " iterations", clock.elapsed(), sppm.image());
        }
    }
    if (out != stdout) std::fclose(out);
    return 0;
}
