#include "render_worker.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/progressive.hpp>
#include <rtlab/render/render_job.hpp>

#include <algorithm>
#include <chrono>
#include <functional>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace rtlab::view {

namespace {

/// Linux's nice value is per thread: rendering threads get a lower priority than the window's, so the window
/// (and Mesa's own rasteriser threads) keep their frame rate while every core renders.
void lower_this_thread() {
    const auto tid = static_cast<id_t>(syscall(SYS_gettid));
    setpriority(PRIO_PROCESS, tid, 10);
}

/// The integrators the viewer offers, by name (rtlab::integrator_name's words). All but sppm render through
/// make_radiance_source; sppm, no radiance source, through make_sppm_renderer, an iteration per pass.
constexpr IntegratorKind kIntegrators[] = {IntegratorKind::whitted, IntegratorKind::direct, IntegratorKind::path,
                                           IntegratorKind::photon, IntegratorKind::sppm};

}  // namespace

const std::vector<std::string>& integrator_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const IntegratorKind kind : kIntegrators) out.emplace_back(integrator_name(kind));
        return out;
    }();
    return names;
}

RenderWorker::RenderWorker(std::filesystem::path scene, SceneLoadOptions load)
    : m_scene_file(std::move(scene)), m_load(std::move(load)), m_thread([this] { run(); }) {}

RenderWorker::~RenderWorker() {
    {
        std::lock_guard lock(m_mutex);
        m_quit = true;
        m_stop = true;
    }
    m_wake.notify_all();
    m_thread.join();
}

std::uint64_t RenderWorker::reload() {
    std::lock_guard lock(m_mutex);
    m_request_time = std::chrono::steady_clock::now();
    m_want_load = true;
    m_wake.notify_all();
    return ++m_request;
}

std::uint64_t RenderWorker::set_camera(std::shared_ptr<const Camera> camera) {
    std::lock_guard lock(m_mutex);
    m_request_time = std::chrono::steady_clock::now();
    m_camera = std::move(camera);
    m_restart = true;
    m_stop = true;
    m_wake.notify_all();
    return ++m_request;
}

std::uint64_t RenderWorker::set_choice(const RenderChoice& choice) {
    std::lock_guard lock(m_mutex);
    m_request_time = std::chrono::steady_clock::now();
    m_choice = choice;
    m_restart = true;
    m_stop = true;
    m_wake.notify_all();
    return ++m_request;
}

std::shared_ptr<const LoadedScene> RenderWorker::scene() const {
    std::lock_guard lock(m_mutex);
    return m_scene;
}

std::pair<int, int> RenderWorker::take_pixels(DisplayBuffer& out) {
    std::lock_guard lock(m_mutex);
    if (m_dirty_begin >= m_dirty_end) return {0, 0};
    // Only the changed rows: copying the whole buffer every frame cost the window a few milliseconds.
    if (out.width != m_display.width || out.height != m_display.height) {
        out = m_display;
        m_dirty_begin = 0;
        m_dirty_end = m_display.height;
    } else {
        const auto w = static_cast<std::ptrdiff_t>(m_display.width);
        const auto b = static_cast<std::ptrdiff_t>(m_dirty_begin), e = static_cast<std::ptrdiff_t>(m_dirty_end);
        std::copy(m_display.mean.begin() + 3 * w * b, m_display.mean.begin() + 3 * w * e, out.mean.begin() + 3 * w * b);
        std::copy(m_display.variance.begin() + 3 * w * b, m_display.variance.begin() + 3 * w * e,
                  out.variance.begin() + 3 * w * b);
        std::copy(m_display.counts.begin() + w * b, m_display.counts.begin() + w * e, out.counts.begin() + w * b);
    }
    const std::pair<int, int> rows{m_dirty_begin, m_dirty_end};
    m_dirty_begin = m_dirty_end = 0;
    return rows;
}

std::vector<WorkerEvent> RenderWorker::take_events() {
    std::lock_guard lock(m_mutex);
    std::vector<WorkerEvent> events(m_events.begin(), m_events.end());
    m_events.clear();
    return events;
}

WorkerStatus RenderWorker::status() const {
    std::lock_guard lock(m_mutex);
    return m_status;
}

std::vector<std::filesystem::path> RenderWorker::watched_files() const {
    std::lock_guard lock(m_mutex);
    std::vector<std::filesystem::path> files{m_scene_file};
    if (m_scene)
        for (const auto& asset : m_scene->assets)
            if (asset.file) files.push_back(asset.file->path);
    return files;
}

void RenderWorker::push(WorkerEvent e) { m_events.push_back(std::move(e)); }

void RenderWorker::load() {
    lower_this_thread();
    // A load is not cancellable (kd-tree builds run to the end), so it runs beside the render: the old scene
    // keeps rendering, and answering the camera, until the new one is ready.
    try {
        auto scene = std::make_shared<LoadedScene>(load_scene(m_scene_file, m_load));
        std::lock_guard lock(m_mutex);
        m_scene = std::move(scene);
        push({m_loaded_once ? WorkerEvent::Kind::reloaded : WorkerEvent::Kind::loaded, 0, m_request, {}});
        m_loaded_once = true;
        m_restart = true;
        m_stop = true;
    } catch (const std::exception& e) {
        std::lock_guard lock(m_mutex);
        push({WorkerEvent::Kind::error, 0, m_request, e.what()});
    }
    std::lock_guard lock(m_mutex);
    m_status.loading = false;
    m_wake.notify_all();
}

void RenderWorker::run() {
    lower_this_thread();
    for (;;) {
        std::shared_ptr<const LoadedScene> scene;
        std::shared_ptr<const Camera> camera;
        RenderChoice choice;
        std::uint64_t request = 0;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] { return m_quit || (m_want_load && !m_status.loading) || (m_restart && m_scene); });
            if (m_quit) break;
            if (m_want_load && !m_status.loading) {
                m_want_load = false;
                m_status.loading = true;
                lock.unlock();
                if (m_loader.joinable()) m_loader.join();  // finished: it cleared `loading`
                m_loader = std::thread([this] { load(); });
                continue;
            }
            m_restart = false;
            m_stop = false;
            scene = m_scene;
            camera = m_camera ? m_camera : m_scene->job.camera;
            choice = m_choice;
            request = m_request;
            m_status.request = request;
        }
        render_passes(scene, camera, choice, request);
    }
    if (m_loader.joinable()) m_loader.join();
}

void RenderWorker::render_passes(const std::shared_ptr<const LoadedScene>& scene,
                                 const std::shared_ptr<const Camera>& camera, const RenderChoice& choice,
                                 std::uint64_t request) {
    ProgressiveSettings settings;
    settings.sequence = choice.sequence;
    settings.seed = choice.seed.value_or(scene->job.settings.seed);
    settings.threads = choice.threads;
    const int width = camera->width(), height = camera->height();
    auto start_display = [&](const std::string& name) {
        std::lock_guard lock(m_mutex);
        if (m_display.width != width || m_display.height != height) {
            const auto n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
            m_display = DisplayBuffer{width, height, std::vector<float>(3 * n), std::vector<float>(3 * n),
                                      std::vector<std::uint32_t>(n)};
        }
        m_status.rendering = true;
        m_status.integrator = name;
        m_status.passes_done = 0;
        m_status.spp = choice.spp;
        m_status.seconds = 0.0;
        m_status.progress = 0.0;
    };
    // Under the lock: rows y0 to y1 changed.
    auto mark_dirty = [&](int y0, int y1) {
        if (m_dirty_begin >= m_dirty_end) {
            m_dirty_begin = y0;
            m_dirty_end = y1;
        } else {
            m_dirty_begin = std::min(m_dirty_begin, y0);
            m_dirty_end = std::max(m_dirty_end, y1);
        }
    };
    bool first_tile = true;
    // Under the lock: the latency from the request to the first finished tile.
    auto note_first_tile = [&] {
        if (first_tile && m_request == request)
            m_status.restart_ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - m_request_time).count();
        first_tile = false;
    };
    ProgressiveCallbacks callbacks;
    callbacks.stop = &m_stop;
    callbacks.progress = [&](const RenderProgress& p) {
        std::lock_guard lock(m_mutex);
        m_status.progress = p.tiles_total > 0 ? static_cast<double>(p.tiles_done) / p.tiles_total : 0.0;
        m_status.seconds = p.seconds;
        m_status.rays_per_second = p.seconds > 0.0 ? static_cast<double>(p.rays.total()) / p.seconds : 0.0;
    };
    // Under the lock: the pass is shown; false when a newer request has come.
    auto pass_done = [&](int passes, const RenderStats& stats) {
        if (m_request != request) return false;
        m_status.passes_done = passes;
        m_status.seconds = stats.seconds;
        m_status.rays_per_second = stats.rays_per_second();
        push({WorkerEvent::Kind::pass, passes, request, {}});
        return true;
    };
    try {
        // No choice yet: the integrator the scene file names, as rtlab-render would use.
        const std::string integrator =
            choice.integrator.empty() ? std::string(integrator_name(scene->job.integrator)) : choice.integrator;
        const auto kind = parse_integrator(integrator);
        if (!kind) throw Error("viewer: unknown integrator '" + integrator + "'");
        // The choice's seed and threads for what the job itself does before the passes (photon's maps).
        RenderJob job = scene->job;
        job.settings.seed = settings.seed;
        job.settings.threads = settings.threads;
        if (*kind == IntegratorKind::sppm) {
            // An iteration is a pass: its camera pass's tiles hold only the direct light, so the window is given the
            // whole image once the iteration's photons are in (no variance: sppm's pixels are no means of samples).
            const auto sppm = make_sppm_renderer(job, *camera, settings);
            sppm->plan_iterations(choice.spp);
            start_display(integrator);
            callbacks.tile = [&](const TileUpdate&) {
                lower_this_thread();
                std::lock_guard lock(m_mutex);
                note_first_tile();
            };
            for (int pass = 0; pass < choice.spp; ++pass) {
                if (!sppm->iterate(callbacks)) break;
                const Image image = sppm->image();
                std::lock_guard lock(m_mutex);
                for (int y = 0; y < height; ++y)
                    for (int x = 0; x < width; ++x) {
                        const std::size_t i =
                            static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
                        const RGB& m = image.at(x, y);
                        for (int c = 0; c < 3; ++c) {
                            m_display.mean[3 * i + static_cast<std::size_t>(c)] = m[c];
                            m_display.variance[3 * i + static_cast<std::size_t>(c)] = 0.0f;
                        }
                        m_display.counts[i] = static_cast<std::uint32_t>(sppm->iterations());
                    }
                mark_dirty(0, height);
                if (!pass_done(pass + 1, sppm->stats())) break;
            }
        } else {
            // photon shoots its maps here; a restart meanwhile sets m_stop, which ends the passes at once too.
            const auto source = make_radiance_source(job, *kind, &m_stop);
            ProgressiveRenderer renderer(*camera, *source, settings);
            renderer.plan_passes(choice.spp);
            start_display(integrator);
            // Each finished tile is copied out at once: the window shows tiles as they finish.
            callbacks.tile = [&](const TileUpdate& t) {
                // The worker that rendered the tile (one of TBB's) gets a lower priority too: nice is per thread and
                // stays, so from its second tile on it renders below the window. (A tbb::task_scheduler_observer
                // would catch the first tile as well, but removing one leaks its record in oneTBB 2021.8.)
                lower_this_thread();
                std::lock_guard lock(m_mutex);
                note_first_tile();
                for (int y = t.y0; y < t.y1; ++y)
                    for (int x = t.x0; x < t.x1; ++x) {
                        const std::size_t i =
                            static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
                        const RGB m = t.buffer.mean(x, y), v = t.buffer.mean_variance(x, y);
                        for (int c = 0; c < 3; ++c) {
                            m_display.mean[3 * i + static_cast<std::size_t>(c)] = m[c];
                            m_display.variance[3 * i + static_cast<std::size_t>(c)] = v[c];
                        }
                        m_display.counts[i] = t.buffer.count(x, y);
                    }
                mark_dirty(t.y0, t.y1);
            };
            for (int pass = 0; pass < choice.spp; ++pass) {
                if (!renderer.render_to(static_cast<std::uint32_t>(pass + 1), callbacks, pass)) break;
                std::lock_guard lock(m_mutex);
                if (!pass_done(pass + 1, renderer.stats())) break;
            }
        }
    } catch (const std::exception& e) {
        std::lock_guard lock(m_mutex);
        push({WorkerEvent::Kind::error, 0, m_request, e.what()});
    }
    std::lock_guard lock(m_mutex);
    m_status.rendering = false;
}

}  // namespace rtlab::view
