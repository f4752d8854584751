#include <rtlab/app/course_app.hpp>
#include <rtlab/app/progress_bar.hpp>
#include <rtlab/app/stop_on_interrupt.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/render/pixel_sampler.hpp>

#include <fmt/core.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <system_error>

namespace rtlab::app {

namespace fs = std::filesystem;

void add_course_options(CLI::App& app, CourseOptions& o) {
    app.add_option("-o,--output", o.output, "output image: .png (tone-mapped), .exr, .hdr or .pfm (linear)")
        ->capture_default_str();
    app.add_option("--width", o.width, "image width in pixels")->check(CLI::Range(1, 1 << 15))->capture_default_str();
    app.add_option("--height", o.height, "image height in pixels")
        ->check(CLI::Range(1, 1 << 15))
        ->capture_default_str();
    app.add_option("--aa", o.aa, "anti-aliasing: none, grid, random, jittered or adaptive (default: the scene's)")
        ->check(CLI::IsMember({"none", "grid", "random", "jittered", "adaptive"}));
    app.add_option("--spp", o.spp, "samples per pixel for grid, random and jittered")
        ->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--aa-threshold", o.threshold, "adaptive: colour difference that splits a square (default 0.3)")
        ->check(CLI::Range(0.0f, 3.0f));
    app.add_option("--aa-depth", o.aa_depth, "adaptive: subdivision depth (default 3)")
        ->check(CLI::Range(0, kMaxAdaptiveDepth));
    app.add_option("--depth", o.max_depth, "reflection and refraction depth (default: the scene's)")
        ->check(CLI::Range(0, 64));
    app.add_option("--threads", o.threads, "render threads (0: every core)")->check(CLI::Range(0, 1024));
    app.add_option("--seed", o.seed, "seed of every random sample (the image is the same for the same seed)");
    app.add_option("--tonemap", o.tonemap, "PNG tone operator: none (clamp), reinhard, ward, exposure or aces")
        ->capture_default_str();
    app.add_flag("-q,--quiet", o.quiet, "no progress bar and no summary");
    app.add_option("--data-dir", o.data_dirs, "folder searched first for textures/ and models/ (repeatable)");
}

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);  // prints the message and "Run with --help for more information."
        return 1;
    }
    return std::nullopt;
}

void apply_course_options(const CourseOptions& o, RenderJob& job) {
    RenderSettings& s = job.settings;
    if (o.aa) s.pattern = parse_pixel_pattern(*o.aa);
    if (o.spp) s.spp = *o.spp;
    // --spp alone asks for more samples: jittered ones unless a pattern is named.
    if (o.spp && !o.aa && (s.pattern == PixelPattern::none || s.pattern == PixelPattern::adaptive) && *o.spp > 1)
        s.pattern = PixelPattern::jittered;
    if (o.threshold) s.adaptive.threshold = *o.threshold;
    if (o.aa_depth) s.adaptive.max_depth = *o.aa_depth;
    if (o.max_depth) job.whitted.max_depth = *o.max_depth;
    s.threads = o.threads;
    s.seed = o.seed;
}

DataPath app_data_path(const std::vector<fs::path>& data_dirs, const fs::path& executable, const char* program) {
    DataPath path = DataPath::from_environment(data_dirs, executable);
    for (const std::string& line : missing_folder_warnings(path, program)) fmt::print(stderr, "{}\n", line);
    return path;
}

DataPath course_data_path(const CourseOptions& o, const fs::path& executable, const char* program) {
    return app_data_path(o.data_dirs, executable, program);
}

fs::path executable_path(const char* argv0) {
    std::error_code ec;
    fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) return self;
    return fs::absolute(argv0 ? argv0 : "", ec);
}

CourseRenderResult run_course_render(const RenderJob& job, const CourseOptions& o, const fs::path& output,
                                     const std::string& label) {
    // Checked before the render, so that a typo in -o does not cost the whole render.
    (void)output_format(output);
    const auto tone = make_tone_operator(make_tone_registry(), o.tonemap);

    CourseRenderResult result;
    RenderResult rendered;
    {
        StopOnInterrupt stop;
        ProgressBar bar(stderr, o.quiet);
        RenderCallbacks callbacks;
        callbacks.stop = &stop.flag();
        if (bar.enabled()) callbacks.progress = [&bar](const RenderProgress& p) { bar.update(p); };
        const std::clock_t cpu_start = std::clock();
        rendered = render_job(job, callbacks);
        result.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
        bar.finish();
        result.interrupted = stop.interrupted();
    }
    result.stats = rendered.stats;
    if (output.has_parent_path()) fs::create_directories(output.parent_path());
    const auto write_start = std::chrono::steady_clock::now();
    write_render_output(rendered.image, output, tone.get());
    result.write_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();
    if (!o.quiet) {
        const RenderStats& s = rendered.stats;
        fmt::print(
            "{}: {}x{} in {:.2f} s ({:.2f} CPU s), {:.2f} Mrays/s ({} camera, {} shadow, {} reflected, {} refracted){} "
            "-> {} (written in {:.2f} s)\n",
            label, rendered.image.width(), rendered.image.height(), s.seconds, result.cpu_seconds,
            s.rays_per_second() * 1e-6, s.rays.camera, s.rays.shadow, s.rays.reflected, s.rays.refracted,
            result.interrupted ? " INTERRUPTED, partial image" : "", output.string(), result.write_seconds);
        std::fflush(stdout);
    }
    return result;
}

void run_with_threads(int threads, const std::function<void()>& body) {
    if (threads <= 0) return body();
    tbb::task_arena(threads).execute(body);
}

int run_app(const char* name, const std::function<int()>& body) {
    try {
        return body();
    } catch (const std::exception& e) {
        fmt::print(stderr, "{}: {}\n", name, e.what());
        return 1;
    }
}

}  // namespace rtlab::app
