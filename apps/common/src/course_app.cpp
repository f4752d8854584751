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

void add_course_options(CommandLine& cli, CourseOptions& o) { cli.add_common(o, make_tone_registry().names()); }

void apply_course_options(const CourseOptions& o, RenderJob& job) {
    RenderSettings& s = job.settings;
    // --spp never changes the pattern: it is the number of samples in the pattern --aa or the scene names.
    if (o.aa) s.pattern = parse_pixel_pattern(*o.aa);
    if (o.spp) s.spp = *o.spp;
    if (o.aa_threshold) s.adaptive.threshold = *o.aa_threshold;
    if (o.aa_depth) s.adaptive.max_depth = *o.aa_depth;
    if (o.max_depth) job.whitted.max_depth = job.path.max_depth = *o.max_depth;
    if (o.integrator) job.integrator = parse_integrator(*o.integrator).value_or(IntegratorKind::whitted);
    if (o.threads) s.threads = *o.threads;
    if (o.seed) s.seed = *o.seed;
    if (o.no_packets) s.packets = false;
    check_sampling(s, o);
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
    // Checked before the render, so that a typo in -o or a missing folder does not cost the whole render.
    (void)output_format(output);
    prepare_output(output);
    const auto tone = make_tone_operator(make_tone_registry(), o.tonemap.value_or("none"));

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

}  // namespace rtlab::app
