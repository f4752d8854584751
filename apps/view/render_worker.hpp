#pragma once
// The viewer's renderer: loads the scene and renders it progressively, one sample per pixel per pass, on its own
// lower-priority threads. The window never waits for it: it asks for a restart (new camera, settings or a
// reload) and copies the pixels the finished tiles left in a shared buffer.
#include <rtlab/core/sample_stream.hpp>
#include <rtlab/render/camera.hpp>
#include <rtlab/render/renderer.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace rtlab::view {

/// The integrators the viewer offers: what the render library has today (a list, so others slot in).
const std::vector<std::string>& integrator_names();

/// \brief What to render: the viewer's choices on top of the scene file.
struct RenderChoice {
    std::string integrator;  ///< empty: the scene's
    SampleSequence sequence = SampleSequence::sobol;
    int spp = 64;                       ///< passes of one sample per pixel until this many
    std::optional<std::uint64_t> seed;  ///< none: the scene's (render.seed or --seed)
    int threads = 0;
};

/// \brief Something the window reports on its output ("pass N", "reloaded", "error ...").
struct WorkerEvent {
    enum class Kind { pass, loaded, reloaded, error } kind;
    int pass = 0;               ///< passes done in this render (kind pass)
    std::uint64_t request = 0;  ///< the request (set_camera, set_choice, reload) the render answers
    std::string message;        ///< the loader's messages (kind error)
};

/// \brief The pixels the window shows: the mean and the variance of the mean of every pixel, and its count.
struct DisplayBuffer {
    int width = 0, height = 0;
    std::vector<float> mean;            ///< 3 per pixel, row-major from the top
    std::vector<float> variance;        ///< 3 per pixel: variance of the mean
    std::vector<std::uint32_t> counts;  ///< samples per pixel
};

/// \brief Where the render is.
struct WorkerStatus {
    bool loading = false, rendering = false;
    int passes_done = 0, spp = 0;
    double seconds = 0.0;  ///< of this render
    double rays_per_second = 0.0;
    double progress = 0.0;      ///< tiles done over tiles of every planned pass
    std::uint64_t request = 0;  ///< the request being rendered
    double restart_ms = 0.0;    ///< from the last request to the first finished tile of its render
    std::string integrator;     ///< the one rendering (the scene's until one is chosen)
};

class RenderWorker {
public:
    RenderWorker(std::filesystem::path scene, SceneLoadOptions load);
    ~RenderWorker();
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    /// Each request stops the render at once and returns its number: events of older renders carry older ones.
    /// Loads the scene again on a thread of its own; the current scene keeps rendering until it is loaded (a
    /// broken file leaves it, and its image, as they are).
    std::uint64_t reload();
    /// Renders with this camera from now on (nullptr: the scene's own).
    std::uint64_t set_camera(std::shared_ptr<const Camera> camera);
    std::uint64_t set_choice(const RenderChoice& choice);
    /// The loaded scene (nullptr before the first successful load).
    std::shared_ptr<const LoadedScene> scene() const;

    /// Copies the rows of the display buffer that finished tiles changed since the last call into `out` (all of
    /// it when its size differs) and returns them as [first, last); an empty range when nothing changed.
    std::pair<int, int> take_pixels(DisplayBuffer& out);
    std::vector<WorkerEvent> take_events();
    WorkerStatus status() const;
    /// The files the loaded scene read (the scene file and the assets found), for live reload.
    std::vector<std::filesystem::path> watched_files() const;

private:
    void run();
    void load();
    void render_passes(const std::shared_ptr<const LoadedScene>& scene, const std::shared_ptr<const Camera>& camera,
                       const RenderChoice& choice, std::uint64_t request);
    void push(WorkerEvent e);

    std::filesystem::path m_scene_file;
    SceneLoadOptions m_load;

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_quit = false;
    bool m_want_load = true, m_loaded_once = false;
    bool m_restart = true;
    std::shared_ptr<const LoadedScene> m_scene;
    std::shared_ptr<const Camera> m_camera;
    RenderChoice m_choice;
    std::atomic<bool> m_stop{false};
    std::uint64_t m_request = 1;
    std::chrono::steady_clock::time_point m_request_time = std::chrono::steady_clock::now();

    DisplayBuffer m_display;
    int m_dirty_begin = 0, m_dirty_end = 0;  // rows changed since take_pixels
    std::deque<WorkerEvent> m_events;
    WorkerStatus m_status;

    std::thread m_loader;  // the load under way, if any
    std::thread m_thread;  // last: started once everything above exists
};

}  // namespace rtlab::view
