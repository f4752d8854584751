// Stochastic progressive photon mapping converges to the path tracer on the Cornell box: the 8x8 block means of the
// sppm image against those of a converged path-traced reference, by iteration. Writes CSV (iterations, photons shot,
// seconds, mean and largest relative block difference, RMSE) and exits 1 unless the mean relative difference ends
// below 1% having fallen. The reference (path, sobol, --ref-spp samples) is cached in --reference FILE.pfm when given;
// its own noise (the two interleaved half-images' block difference, halved) is printed, the floor of what can be
// measured against it.
//   rtlab_render_sppm_convergence [--scene FILE] [--size N] [--ref-spp N] [--iterations N] [--photons N]
//                                 [--threads N] [--csv FILE] [--reference FILE.pfm]
#include "image_compare.hpp"

#include <rtlab/render/image_output.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sampled_lights.hpp>
#include <rtlab/render/sppm.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

using namespace rtlab;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
    fs::path scene_file = fs::path(RTLAB_SOURCE_DIR) / "scenes/cornell_box.json";
    std::string csv, reference_file;
    int size = 32, ref_spp = 16384, iterations = 1024, threads = 0;
    std::uint32_t photons = 20000;
    CLI::App app{"sppm_convergence: sppm against a path-traced reference by iteration count, 8x8 block means"};
    app.add_option("--scene", scene_file, "scene file (default: scenes/cornell_box.json)");
    app.add_option("--size", size, "image width and height")->check(CLI::Range(8, 1 << 14));
    app.add_option("--ref-spp", ref_spp, "samples per pixel of the path-traced reference")->check(CLI::PositiveNumber);
    app.add_option("--iterations", iterations, "largest iteration count")->check(CLI::PositiveNumber);
    app.add_option("--photons", photons, "photons per iteration")->check(CLI::PositiveNumber);
    app.add_option("--threads", threads, "render threads (0: every core)")->check(CLI::NonNegativeNumber);
    app.add_option("--csv", csv, "write the results as CSV");
    app.add_option("--reference", reference_file, "reference image: read if it exists, else rendered and written");
    CLI11_PARSE(app, argc, argv);
    SceneLoadOptions load;
    load.use_environment = false;
    load.overrides.width = load.overrides.height = size;
    load.overrides.threads = threads;
    LoadedScene scene = load_scene(scene_file, load);
    RenderJob& job = scene.job;
    job.settings.threads = threads;
    job.photons.photons = photons;

    Image reference;
    double reference_noise = -1.0;  // unknown for a cached reference
    if (!reference_file.empty() && fs::exists(reference_file)) {
        reference = read_image(reference_file, ColorEncoding::linear);
        std::fprintf(stderr, "reference: %s\n", reference_file.c_str());
        if (std::FILE* f = std::fopen((reference_file + ".noise").c_str(), "r")) {
            if (std::fscanf(f, "%lf", &reference_noise) != 1) reference_noise = -1.0;
            std::fclose(f);
        }
    }
    if (reference.width() != size || reference.height() != size) {
        RenderJob ref = job;
        ref.integrator = IntegratorKind::path;
        ref.settings.pattern = PixelPattern::sobol;
        ref.settings.spp = ref_spp;
        ref.settings.seed = 1000;
        const auto start = std::chrono::steady_clock::now();
        const RenderResult r = render_job(ref);
        reference = r.image;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const bench::BlockDifference halves =
            bench::block_difference(r.buffer->half_mean_image(0), r.buffer->half_mean_image(1), 8);
        // Each half-image has twice the whole's variance, independently: their difference has four times it, so
        // the whole's noise is about half the halves' difference.
        reference_noise = 0.5 * halves.mean;
        std::fprintf(stderr,
                     "reference: path, %d spp, %.1f s; its block noise about %.3g%% (half-images %.3g%% apart)\n",
                     ref_spp, seconds, 100.0 * reference_noise, 100.0 * halves.mean);
        if (!reference_file.empty()) {
            std::FILE* f = std::fopen((reference_file + ".noise").c_str(), "w");
            if (f) std::fprintf(f, "%.6g\n", reference_noise), std::fclose(f);
        }
        if (!reference_file.empty()) write_image(reference, reference_file);
    }

    const SampledLights sampled = make_sampled_lights(job.scene, job.lights, job.whitted);
    ProgressiveSettings settings;
    settings.seed = 1;
    settings.threads = threads;
    SppmRenderer sppm(*job.camera, *sampled.scene, sampled.lights, sampled.sphere, job.path, job.photons, settings);
    std::FILE* out = csv.empty() ? stdout : std::fopen(csv.c_str(), "w");
    if (!out) {
        std::fprintf(stderr, "sppm_convergence: cannot write %s\n", csv.c_str());
        return 1;
    }
    std::fprintf(out, "iterations,photons,seconds,block_mean_relative,block_max_relative,rmse,reference_block_noise\n");
    double first = -1.0, last = 0.0;
    for (int next = 1; next <= iterations; next *= 2) {
        while (sppm.iterations() < next) sppm.iterate();
        const Image image = sppm.image();
        const bench::BlockDifference d = bench::block_difference(image, reference, 8);
        std::fprintf(out, "%d,%llu,%.3f,%.5g,%.5g,%.5g,%.4g\n", next,
                     static_cast<unsigned long long>(sppm.photons_shot()), sppm.stats().seconds, d.mean, d.largest,
                     bench::rmse(image, reference), reference_noise);
        std::fflush(out);
        if (first < 0.0) first = d.mean;
        last = d.mean;
    }
    if (out != stdout) std::fclose(out);
    std::fprintf(stderr, "mean relative block difference %.3g%% after 1 iteration, %.3g%% after %d\n", 100.0 * first,
                 100.0 * last, sppm.iterations());
    return last < 0.01 && last < first ? 0 : 1;
}
