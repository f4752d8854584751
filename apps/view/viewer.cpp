#include "viewer.hpp"

#include "commands.hpp"
#include "display_tone.hpp"
#include "file_watch.hpp"
#include "image_view.hpp"
#include "orbit_camera.hpp"
#include "render_worker.hpp"

#include <rtlab/app/course_app.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/srgb.hpp>
#include <rtlab/render/image_output.hpp>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <stb_image_write.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

namespace rtlab::view {

namespace {

constexpr float kPanelWidth = 340.0f;  // window pixels, times the content scale

/// Set by any input (GLFW calls these before Dear ImGui's own, which it chains): the window draws again.
std::atomic<bool> g_input{true};

/// Lines the viewer prints for whoever drives it (tests wait for them): flushed at once.
void say(const std::string& line) {
    std::fputs((line + "\n").c_str(), stdout);
    std::fflush(stdout);
}

/// Commands from --script and standard input, in order.
class CommandQueue {
public:
    void push(Command c) {
        std::lock_guard lock(m_mutex);
        m_commands.push_back(std::move(c));
    }
    bool front(Command& c) {
        std::lock_guard lock(m_mutex);
        if (m_commands.empty()) return false;
        c = m_commands.front();
        return true;
    }
    bool empty() {
        std::lock_guard lock(m_mutex);
        return m_commands.empty();
    }
    void pop() {
        std::lock_guard lock(m_mutex);
        m_commands.pop_front();
    }

private:
    std::mutex m_mutex;
    std::deque<Command> m_commands;
};

bool write_png_rgb(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgb) {
    return stbi_write_png(file.c_str(), width, height, 3, rgb.data(), width * 3) != 0;
}

float parse_float(const std::string& text, const std::string& what) {
    try {
        std::size_t used = 0;
        const float v = std::stof(text, &used);
        if (used == text.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    throw Error("rtlab-view: " + what + ": '" + text + "' is not a number");
}

class Viewer {
public:
    Viewer(const app::ViewOptions& options, SceneLoadOptions load, GLFWwindow* window)
        : m_options(options), m_window(window), m_worker(options.scene, std::move(load)) {
        m_choice.integrator = options.integrator;
        if (options.screenshot_passes)
            m_choice.spp = *options.screenshot_passes;
        else if (options.common.spp)
            m_choice.spp = *options.common.spp;
        m_choice.threads = options.common.threads_or_all();
        if (options.common.aa == "random") m_choice.sequence = SampleSequence::independent;
        if (!options.common.output.empty())
            std::snprintf(m_path, sizeof m_path, "%s", options.common.output.c_str());  // where "save" writes
        m_stops = static_cast<float>(options.exposure.value_or(0.0));
        m_worker.set_choice(m_choice);
        m_request = m_worker.set_camera(nullptr);
    }

    int run(CommandQueue& commands) {
        using Clock = std::chrono::steady_clock;
        auto last_fps = Clock::now(), frame_start = Clock::now();
        int frames = 0;
        double work_sum = 0.0, work_max = 0.0;
        while (!glfwWindowShouldClose(m_window) && !m_quit) {
            // About 60 frames a second: wait for input only for what is left of this frame's 1/60 s.
            // Idle (nothing rendering, no input for a while): wait up to 0.1 s, for the file watch and commands.
            const double spent = std::chrono::duration<double>(Clock::now() - frame_start).count();
            const double frame = m_idle ? 0.1 : 1.0 / 60.0;
            if (spent < frame)
                glfwWaitEventsTimeout(frame - spent);
            else
                glfwPollEvents();
            frame_start = Clock::now();
            if (g_input.exchange(false)) m_last_input = frame_start;
            handle_events();
            if (m_exit_status) return *m_exit_status;
            const auto [first, last] = m_worker.take_pixels(m_pixels);
            if (first < last) {
                m_view->upload(m_pixels, first, last);
                // Reinhard's and Ward's statistics change with the pixels; the others need none.
                m_tone_dirty = m_tone_dirty || m_tone.op == ToneChoice::reinhard || m_tone.op == ToneChoice::ward;
            }
            for (int pass : m_passes_to_print) say("pass " + std::to_string(pass));
            m_passes_to_print.clear();
            if (m_watch && m_watch->poll()) m_request = m_worker.reload();
            run_commands(commands);
            // A saved window shows the statistics of exactly the pixels in it.
            if (!m_screenshot.empty() ||
                (m_options.screenshot_passes && m_passes_shown >= *m_options.screenshot_passes))
                m_last_tone_time = {};
            // A window with nothing new is not drawn again: Mesa's software rasteriser would take a core from the
            // renderer for an unchanged picture.
            const WorkerStatus status = m_worker.status();
            m_idle = first >= last && !status.rendering && !status.loading && m_screenshot.empty() &&
                     !m_options.screenshot_passes && commands.empty() &&
                     frame_start - m_last_input > std::chrono::milliseconds(500) &&
                     frame_start - m_last_draw < std::chrono::seconds(1);
            if (m_idle) continue;
            m_last_draw = frame_start;
            draw_frame();
            if (!m_screenshot.empty()) {
                save_screenshot(m_screenshot);
                m_screenshot.clear();
                commands.pop();
                m_blocked = false;
            }
            if (m_options.screenshot_passes && m_passes_shown >= *m_options.screenshot_passes) {
                // The window asked for its size when the scene loaded; a window manager that refuses it must not
                // hold the run forever: after two seconds the window is saved as it is.
                if (m_passes_done_at == Clock::time_point{}) m_passes_done_at = frame_start;
                if (frame_ready() || frame_start - m_passes_done_at > std::chrono::seconds(2)) {
                    save_screenshot(m_options.screenshot_file);
                    return app::kExitDone;
                }
            }
            glfwSwapBuffers(m_window);
            ++frames;
            const auto now = Clock::now();
            const double work = std::chrono::duration<double, std::milli>(now - frame_start).count();
            work_sum += work;
            work_max = std::max(work_max, work);
            const double elapsed = std::chrono::duration<double>(now - last_fps).count();
            if (elapsed >= 1.0) {
                m_fps = frames / elapsed;
                m_frame_ms = work_sum / frames;
                m_frame_max_ms = work_max;
                frames = 0;
                work_sum = work_max = 0.0;
                last_fps = now;
            }
        }
        return app::kExitDone;
    }

    void create_view() { m_view = std::make_unique<ImageView>(); }

private:
    // --- the renderer's news -------------------------------------------------------------------------------------
    void handle_events() {
        for (const WorkerEvent& e : m_worker.take_events()) {
            switch (e.kind) {
                case WorkerEvent::Kind::loaded:
                case WorkerEvent::Kind::reloaded:
                    on_loaded(e.kind == WorkerEvent::Kind::reloaded);
                    break;
                case WorkerEvent::Kind::error:
                    on_error(e.message);
                    break;
                case WorkerEvent::Kind::pass:
                    if (e.request != m_request) break;  // a render the window no longer wants
                    m_passes_shown = e.pass;
                    m_passes_to_print.push_back(e.pass);
                    break;
            }
        }
    }

    void on_loaded(bool reload) {
        const auto scene = m_worker.scene();
        m_error.clear();
        if (!reload || !m_camera.changed()) m_camera = OrbitCamera(*scene->job.camera);
        m_scene_camera = scene->job.camera;
        m_image_width = scene->job.camera->width();
        m_image_height = scene->job.camera->height();
        if (!reload) {
            parse_tone_choice(scene->tone_name, m_tone.op);
            // The file's samples per pixel when it samples more than once per pixel; else the viewer's default.
            const RenderSettings& file = scene->job.settings;
            if (!m_options.common.spp && !m_options.screenshot_passes && file.pattern != PixelPattern::none &&
                file.pattern != PixelPattern::adaptive && file.spp > 1) {
                m_choice.spp = file.spp;
                m_worker.set_choice(m_choice);
            }
            fit_window();
        }
        m_request = m_worker.set_camera(m_camera.changed() ? m_camera.make(m_scene_camera) : nullptr);
        m_passes_shown = 0;
        try {
            if (!m_watch) m_watch = std::make_unique<FileWatch>();
            m_watch->watch(m_worker.watched_files());
        } catch (const Error& e) {
            say(std::string("warning: ") + e.what());
        }
        say(reload ? "reloaded" : "loaded " + std::to_string(m_image_width) + "x" + std::to_string(m_image_height));
        if (reload) ++m_reloads;
    }

    void on_error(const std::string& message) {
        m_error = message;
        ++m_errors;
        std::istringstream lines(message);
        for (std::string line; std::getline(lines, line);) say("error: " + line);
        // Without a window to look at (a screenshot run), a scene that never loaded ends the run as a bad scene
        // does for every rtlab app: its messages on stderr, exit status 1.
        if (m_options.screenshot_passes && !m_worker.scene()) {
            std::fprintf(stderr, "rtlab-view: %s\n", message.c_str());
            m_exit_status = app::kExitBadInput;
            return;
        }
        // A first load that failed still watches the scene file, so that fixing it loads it.
        if (!m_watch) {
            m_watch = std::make_unique<FileWatch>();
            m_watch->watch({m_options.scene});
        }
    }

    // --- layout --------------------------------------------------------------------------------------------------
    float scale() const {
        int fw = 0, fh = 0, ww = 0, wh = 0;
        glfwGetFramebufferSize(m_window, &fw, &fh);
        glfwGetWindowSize(m_window, &ww, &wh);
        return ww > 0 ? static_cast<float>(fw) / static_cast<float>(ww) : 1.0f;
    }
    int panel_width() const { return static_cast<int>(kPanelWidth * scale()); }

    void fit_window() {
        const float s = scale();
        const int w = static_cast<int>(std::ceil((static_cast<float>(m_image_width) + kPanelWidth * s) / s));
        const int h = static_cast<int>(std::ceil(static_cast<float>(std::max(m_image_height, 560)) / s));
        glfwSetWindowSize(m_window, w, h);
    }

    /// The screenshot needs the window at its size and the pixels of the last pass on screen.
    bool frame_ready() const {
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(m_window, &fw, &fh);
        return fw >= panel_width() + m_image_width && fh >= m_image_height;
    }

    ViewParams view_params() {
        ViewParams p;
        // The statistics take a pass over every pixel: while tiles come in, four times a second is enough.
        const auto now = std::chrono::steady_clock::now();
        const bool stale =
            m_tone_dirty && (now - m_last_tone_time > std::chrono::milliseconds(250) || !m_worker.status().rendering);
        if (stale || m_tone.op != m_last_tone_op || m_stops != m_last_stops) {
            m_last_tone_time = now;
            std::vector<std::uint8_t> rendered(m_pixels.counts.size());
            for (std::size_t i = 0; i < rendered.size(); ++i) rendered[i] = m_pixels.counts[i] > 0;
            m_tone = tone_params(m_tone.op, m_stops, m_pixels.mean, rendered);
            m_tone_dirty = false;
            m_last_tone_op = m_tone.op;
            m_last_stops = m_stops;
        }
        p.tone = m_tone;
        p.mode = m_mode;
        p.zoom = m_zoom;
        p.origin_x = static_cast<float>(panel_width()) + m_pan_x;
        p.origin_y = m_pan_y;
        p.split = m_split;
        return p;
    }

    // --- input ---------------------------------------------------------------------------------------------------
    void camera_moved() {
        m_request = m_worker.set_camera(m_camera.changed() ? m_camera.make(m_scene_camera) : nullptr);
        m_passes_shown = 0;
    }

    void handle_mouse(const ViewParams& p, int fb_width, int fb_height) {
        ImGuiIO& io = ImGui::GetIO();
        const float s = scale();
        double cx = 0, cy = 0;
        glfwGetCursorPos(m_window, &cx, &cy);
        const float x = static_cast<float>(cx) * s, y = static_cast<float>(cy) * s;
        const bool over_image = x >= static_cast<float>(panel_width()) && x < static_cast<float>(fb_width) && y >= 0 &&
                                y < static_cast<float>(fb_height) && !io.WantCaptureMouse;
        m_hover_x = static_cast<int>(std::floor((x - p.origin_x) / p.zoom));
        m_hover_y = static_cast<int>(std::floor((y - p.origin_y) / p.zoom));
        if (!over_image) m_hover_x = m_hover_y = -1;
        if (!over_image && !m_dragging) return;
        const ImVec2 d = io.MouseDelta;
        const float dx = d.x * s, dy = d.y * s;
        m_dragging = ImGui::IsMouseDown(0) || ImGui::IsMouseDown(1) || ImGui::IsMouseDown(2);
        if ((dx != 0.0f || dy != 0.0f) && m_camera.movable()) {
            if (ImGui::IsMouseDown(0)) {
                m_camera.orbit(-dx * 0.005f, dy * 0.005f);
                camera_moved();
            } else if (ImGui::IsMouseDown(1)) {
                const float h = static_cast<float>(m_image_height) * p.zoom;
                m_camera.pan(-dx / h, dy / h);
                camera_moved();
            }
        }
        if (ImGui::IsMouseDown(2)) {
            m_pan_x += dx;
            m_pan_y += dy;
        }
        if (io.MouseWheel != 0.0f && over_image) {
            if (io.KeyCtrl || io.KeyShift) {
                zoom_about(std::exp2(std::round(io.MouseWheel)), x, y);
            } else if (m_camera.movable()) {
                m_camera.dolly(0.1f * io.MouseWheel);
                camera_moved();
            }
        }
    }

    void zoom_about(float factor, float x, float y) {
        const float new_zoom = std::clamp(m_zoom * factor, 0.125f, 64.0f);
        const float ox = static_cast<float>(panel_width()) + m_pan_x;
        // Keep the image point under (x, y) where it is.
        m_pan_x = x - (x - ox) * new_zoom / m_zoom - static_cast<float>(panel_width());
        m_pan_y = y - (y - m_pan_y) * new_zoom / m_zoom;
        m_zoom = new_zoom;
    }

    void handle_keys() {
        if (ImGui::GetIO().WantCaptureKeyboard) return;
        if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) m_quit = true;
        if (ImGui::IsKeyPressed('R')) reset_camera();
        if (ImGui::IsKeyPressed('C')) say(m_camera.json_snippet());
        if (ImGui::IsKeyPressed('1')) m_zoom = 1.0f, m_pan_x = m_pan_y = 0.0f;
        if (ImGui::IsKeyPressed('V')) m_mode = m_mode == ViewMode::variance ? ViewMode::image : ViewMode::variance;
    }

    void reset_camera() {
        m_camera.reset();
        camera_moved();
    }

    // --- commands ------------------------------------------------------------------------------------------------
    void run_commands(CommandQueue& commands) {
        Command c;
        while (!m_blocked && commands.front(c)) {
            if (c.name == "wait") {
                if (c.args[0] == "pass") {
                    if (m_passes_shown < static_cast<int>(parse_float(c.args[1], "wait pass"))) return;
                } else if (c.args[0] == "reloaded") {
                    if (m_reloads <= m_reloads_waited) return;
                    ++m_reloads_waited;
                } else {
                    if (m_errors <= m_errors_waited) return;
                    ++m_errors_waited;
                }
            } else if (c.name == "screenshot") {
                m_screenshot = c.args[0];
                m_blocked = true;  // popped once written, after this frame
                return;
            } else {
                try {
                    execute(c);
                } catch (const Error& e) {
                    say(std::string("error: ") + e.what());
                }
            }
            commands.pop();
        }
    }

    void execute(const Command& c) {
        const auto& a = c.args;
        if (c.name == "quit") {
            m_quit = true;
        } else if (c.name == "orbit") {
            m_camera.orbit(glm::radians(parse_float(a[0], "orbit")), glm::radians(parse_float(a[1], "orbit")));
            camera_moved();
        } else if (c.name == "pan") {
            m_camera.pan(parse_float(a[0], "pan"), parse_float(a[1], "pan"));
            camera_moved();
        } else if (c.name == "dolly") {
            m_camera.dolly(parse_float(a[0], "dolly"));
            camera_moved();
        } else if (c.name == "reset") {
            reset_camera();
        } else if (c.name == "print-camera") {
            say(m_camera.json_snippet());
        } else if (c.name == "tone") {
            if (!parse_tone_choice(a[0], m_tone.op)) throw Error("rtlab-view: tone: unknown operator '" + a[0] + "'");
        } else if (c.name == "exposure") {
            m_stops = parse_float(a[0], "exposure");
        } else if (c.name == "view") {
            if (a[0] == "image")
                m_mode = ViewMode::image;
            else if (a[0] == "variance")
                m_mode = ViewMode::variance;
            else if (a[0] == "compare")
                m_mode = ViewMode::compare;
            else
                throw Error("rtlab-view: view: image, variance or compare, not '" + a[0] + "'");
        } else if (c.name == "reference") {
            load_reference(a[0]);
        } else if (c.name == "zoom") {
            m_zoom = std::clamp(parse_float(a[0], "zoom"), 0.125f, 64.0f);
        } else if (c.name == "inspect") {
            say(inspect(static_cast<int>(parse_float(a[0], "inspect")),
                        static_cast<int>(parse_float(a[1], "inspect"))));
        } else if (c.name == "spp") {
            m_choice.spp = std::clamp(static_cast<int>(parse_float(a[0], "spp")), 1, 65536);
            m_request = m_worker.set_choice(m_choice);
            m_passes_shown = 0;
        } else if (c.name == "stats") {
            const WorkerStatus st = m_worker.status();
            char text[200];
            std::snprintf(text, sizeof text,
                          "stats fps %.1f frame_ms %.2f frame_max_ms %.2f restart_ms %.1f rays_per_s %.3g passes %d",
                          m_fps, m_frame_ms, m_frame_max_ms, st.restart_ms, st.rays_per_second, st.passes_done);
            say(text);
        } else if (c.name == "save") {
            save_image(a[0]);
        }
    }

    std::string inspect(int x, int y) const {
        if (x < 0 || y < 0 || x >= m_pixels.width || y >= m_pixels.height) return "pixel outside the image";
        const std::size_t i =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(m_pixels.width) + static_cast<std::size_t>(x);
        char text[240];
        // The standard deviation of the mean: how far the pixel may still move.
        std::snprintf(text, sizeof text, "pixel %d %d %.6g %.6g %.6g samples %u sd %.3g %.3g %.3g", x, y,
                      static_cast<double>(m_pixels.mean[3 * i]), static_cast<double>(m_pixels.mean[3 * i + 1]),
                      static_cast<double>(m_pixels.mean[3 * i + 2]), m_pixels.counts[i],
                      std::sqrt(static_cast<double>(m_pixels.variance[3 * i])),
                      std::sqrt(static_cast<double>(m_pixels.variance[3 * i + 1])),
                      std::sqrt(static_cast<double>(m_pixels.variance[3 * i + 2])));
        return text;
    }

    Image mean_image() const {
        Image image(std::max(m_pixels.width, 1), std::max(m_pixels.height, 1));
        for (int y = 0; y < m_pixels.height; ++y)
            for (int x = 0; x < m_pixels.width; ++x) {
                const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(m_pixels.width) +
                                           static_cast<std::size_t>(x));
                image.at(x, y) = RGB(m_pixels.mean[i], m_pixels.mean[i + 1], m_pixels.mean[i + 2]);
            }
        return image;
    }

    /// PNG as displayed (the shader's mapping on the CPU); EXR, HDR and PFM linear.
    void save_image(const std::filesystem::path& file) {
        const Image image = mean_image();
        if (file.extension() == ".png") {
            std::vector<std::uint8_t> rgb(3 * image.pixel_count());
            std::vector<RGB> mapped(image.pixel_count());
            for (std::size_t i = 0; i < mapped.size(); ++i) mapped[i] = tone_map(m_tone, image.pixels()[i]);
            srgb_encode_8bit(mapped.data(), mapped.size(), rgb.data());
            if (!write_png_rgb(file, image.width(), image.height(), rgb))
                throw Error("rtlab-view: cannot write " + file.string());
        } else {
            write_render_output(image, file);
        }
        say("saved " + file.string());
    }

    void load_reference(const std::filesystem::path& file) {
        const Image reference = read_image(file);
        Image fitted(std::max(m_image_width, 1), std::max(m_image_height, 1));
        for (int y = 0; y < std::min(fitted.height(), reference.height()); ++y)
            for (int x = 0; x < std::min(fitted.width(), reference.width()); ++x) fitted.at(x, y) = reference.at(x, y);
        m_view->set_reference(fitted);
        m_mode = ViewMode::compare;
    }

    void save_screenshot(const std::filesystem::path& file) {
        int w = 0, h = 0;
        glfwGetFramebufferSize(m_window, &w, &h);
        std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
        std::vector<std::uint8_t> flipped(rgb.size());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadBuffer(GL_BACK);
        glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
        const std::size_t row = static_cast<std::size_t>(w) * 3;
        for (int y = 0; y < h; ++y)
            std::copy_n(rgb.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(h - 1 - y) * row), row,
                        flipped.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * row));
        if (!write_png_rgb(file, w, h, flipped)) throw Error("rtlab-view: cannot write " + file.string());
        say("saved " + file.string());
    }

    // --- drawing -------------------------------------------------------------------------------------------------
    void draw_frame() {
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(m_window, &fw, &fh);
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const ViewParams p = view_params();
        handle_mouse(p, fw, fh);
        handle_keys();
        const int panel = panel_width();
        const std::string rect = std::to_string(panel + static_cast<int>(m_pan_x)) + " " +
                                 std::to_string(static_cast<int>(m_pan_y)) + " " +
                                 std::to_string(static_cast<int>(static_cast<float>(m_image_width) * m_zoom)) + " " +
                                 std::to_string(static_cast<int>(static_cast<float>(m_image_height) * m_zoom));
        if (rect != m_last_rect && m_image_width > 0) {
            say("image " + rect);
            m_last_rect = rect;
        }
        draw_panel(static_cast<float>(panel), static_cast<float>(fh));
        ImGui::Render();
        glViewport(0, 0, fw, fh);
        glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        m_view->draw(fw, fh, panel, fw, p);
        glViewport(0, 0, fw, fh);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }

    void draw_panel(float width, float height) {
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(width, height));
        ImGui::Begin("rtlab-view", nullptr,
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoTitleBar);
        const WorkerStatus s = m_worker.status();
        ImGui::TextWrapped("%s", m_options.scene.filename().c_str());
        ImGui::Text("%dx%d  %s", m_image_width, m_image_height,
                    s.loading ? "loading" : (s.rendering ? "rendering" : "done"));
        ImGui::ProgressBar(static_cast<float>(s.progress));
        ImGui::Text("spp %d / %d   %.2f s", s.passes_done, s.spp, s.seconds);
        ImGui::Text("%.3g rays/s", s.rays_per_second);
        ImGui::Text("%.0f fps (frame %.1f ms)  restart %.1f ms", m_fps, m_frame_ms, s.restart_ms);
        ImGui::Separator();

        const std::string& current = m_choice.integrator.empty() ? s.integrator : m_choice.integrator;
        int integrator = static_cast<int>(std::find(integrator_names().begin(), integrator_names().end(), current) -
                                          integrator_names().begin());
        if (combo("integrator", integrator, integrator_names())) {
            m_choice.integrator = integrator_names()[static_cast<std::size_t>(integrator)];
            restart();
        }
        int sequence = static_cast<int>(m_choice.sequence);
        if (combo("anti-aliasing", sequence, {"random", "sobol"})) {
            m_choice.sequence = static_cast<SampleSequence>(sequence);
            restart();
        }
        int spp = m_choice.spp;
        if (ImGui::InputInt("spp", &spp, 16, 256, ImGuiInputTextFlags_EnterReturnsTrue)) {
            m_choice.spp = std::clamp(spp, 1, 65536);
            restart();
        }
        ImGui::Separator();
        int op = static_cast<int>(m_tone.op);
        if (combo("tone", op, tone_choice_names())) m_tone.op = static_cast<ToneChoice>(op);
        ImGui::SliderFloat("exposure", &m_stops, -10.0f, 10.0f, "%.2f stops");
        int mode = static_cast<int>(m_mode);
        ImGui::RadioButton("image", &mode, 0);
        ImGui::SameLine();
        ImGui::RadioButton("variance", &mode, 1);
        ImGui::SameLine();
        ImGui::RadioButton("A/B", &mode, 2);
        m_mode = static_cast<ViewMode>(mode);
        if (m_mode == ViewMode::compare) ImGui::SliderFloat("split", &m_split, 0.0f, 1.0f);
        ImGui::InputText("file", m_path, sizeof m_path);
        if (ImGui::Button("save")) run_guarded([&] { save_image(m_path); });
        ImGui::SameLine();
        if (ImGui::Button("load A/B reference")) run_guarded([&] { load_reference(m_path); });
        ImGui::TextWrapped("zoom %.3gx (shift+wheel; middle drag pans; key 1: 1:1)", static_cast<double>(m_zoom));
        ImGui::Separator();
        ImGui::TextWrapped("camera: drag orbits, right drag pans, wheel zooms");
        if (ImGui::Button("reset camera (R)")) reset_camera();
        ImGui::SameLine();
        if (ImGui::Button("print camera (C)")) say(m_camera.json_snippet());
        ImGui::Separator();
        if (m_hover_x >= 0 && m_hover_y >= 0 && m_hover_x < m_pixels.width && m_hover_y < m_pixels.height)
            ImGui::TextWrapped("%s", inspect(m_hover_x, m_hover_y).c_str());
        else
            ImGui::TextDisabled("pixel: hover over the image");
        if (!m_error.empty()) {
            ImGui::Separator();
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
            ImGui::TextWrapped("%s", m_error.c_str());
            ImGui::PopStyleColor();
        }
        ImGui::End();
    }

    /// A drop-down list; an index outside the names (nothing chosen yet: the scene still loading) shows no name.
    static bool combo(const char* label, int& index, const std::vector<std::string>& names) {
        bool changed = false;
        const bool known = index >= 0 && static_cast<std::size_t>(index) < names.size();
        if (ImGui::BeginCombo(label, known ? names[static_cast<std::size_t>(index)].c_str() : "")) {
            for (std::size_t i = 0; i < names.size(); ++i)
                if (ImGui::Selectable(names[i].c_str(), static_cast<int>(i) == index)) {
                    index = static_cast<int>(i);
                    changed = true;
                }
            ImGui::EndCombo();
        }
        return changed;
    }

    void restart() {
        m_request = m_worker.set_choice(m_choice);
        m_passes_shown = 0;
    }

    template <class F>
    void run_guarded(F f) {
        try {
            f();
        } catch (const std::exception& e) {
            m_error = e.what();
        }
    }

    const app::ViewOptions& m_options;
    GLFWwindow* m_window;
    RenderWorker m_worker;
    std::unique_ptr<ImageView> m_view;
    std::unique_ptr<FileWatch> m_watch;
    RenderChoice m_choice;
    OrbitCamera m_camera;
    std::shared_ptr<const Camera> m_scene_camera;
    DisplayBuffer m_pixels;
    ToneParams m_tone;
    ToneChoice m_last_tone_op = ToneChoice::none;
    float m_stops = 0.0f, m_last_stops = 0.0f;
    bool m_tone_dirty = true;
    std::chrono::steady_clock::time_point m_last_tone_time;
    ViewMode m_mode = ViewMode::image;
    float m_zoom = 1.0f, m_pan_x = 0.0f, m_pan_y = 0.0f, m_split = 0.5f;
    int m_image_width = 0, m_image_height = 0;
    int m_hover_x = -1, m_hover_y = -1;
    bool m_dragging = false;
    std::uint64_t m_request = 0;
    int m_passes_shown = 0;
    std::vector<int> m_passes_to_print;
    int m_reloads = 0, m_reloads_waited = 0, m_errors = 0, m_errors_waited = 0;
    std::string m_error, m_last_rect;
    std::filesystem::path m_screenshot;
    bool m_blocked = false, m_quit = false;
    bool m_idle = false;
    std::chrono::steady_clock::time_point m_passes_done_at;  // screenshot run: when the last pass came
    std::chrono::steady_clock::time_point m_last_input, m_last_draw;
    std::optional<int> m_exit_status;
    double m_fps = 0.0, m_frame_ms = 0.0, m_frame_max_ms = 0.0;  // over the last second
    char m_path[512] = "view.png";
};

std::string g_glfw_error;

void note_input(GLFWwindow* window) {
    (void)window;
    g_input = true;
}

void install_input_callbacks(GLFWwindow* window) {
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) { note_input(w); });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int, int, int) { note_input(w); });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double) { note_input(w); });
    glfwSetKeyCallback(window, [](GLFWwindow* w, int, int, int, int) { note_input(w); });
    glfwSetCharCallback(window, [](GLFWwindow* w, unsigned) { note_input(w); });
    glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { note_input(w); });
    glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { note_input(w); });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { note_input(w); });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { note_input(w); });
}

}  // namespace

int run_viewer(const app::ViewOptions& options, const char* argv0) {
    SceneLoadOptions load;
    load.data_path = app::app_data_path(options.common.data_dirs, app::executable_path(argv0), "rtlab-view");
    load.overrides.width = options.common.width;
    load.overrides.height = options.common.height;
    load.overrides.threads = options.common.threads;
    load.overrides.tonemap = options.common.tonemap;
    load.overrides.seed = options.common.seed;
    load.overrides.max_depth = options.common.max_depth;
    if (!options.screenshot_file.empty()) app::prepare_output(options.screenshot_file);

    // Never freed: the standard-input thread may still push to it while the program ends.
    CommandQueue& commands = *new CommandQueue;
    if (!options.script.empty()) {
        std::ifstream in(options.script);
        if (!in) throw Error(options.script.string() + ": cannot read the script");
        int n = 0;
        for (std::string line; std::getline(in, line);)
            if (auto c = parse_command(line, options.script.string() + ":" + std::to_string(++n))) commands.push(*c);
    }

    glfwSetErrorCallback([](int, const char* text) { g_glfw_error = text; });
    if (!glfwInit()) {
        std::fprintf(stderr, "rtlab-view: no display: %s\n",
                     g_glfw_error.empty() ? "GLFW failed" : g_glfw_error.c_str());
        return app::kExitBadInput;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    GLFWwindow* window =
        glfwCreateWindow(1000, 600, ("rtlab-view " + options.scene.string()).c_str(), nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "rtlab-view: no OpenGL 3.3 window: %s\n", g_glfw_error.c_str());
        glfwTerminate();
        return app::kExitBadInput;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(0);  // the loop paces itself; a blocking swap would hold the window behind the display
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    float sx = 1.0f, sy = 1.0f;
    glfwGetWindowContentScale(window, &sx, &sy);
    ImGui::GetStyle().ScaleAllSizes(sx);
    ImGui::GetIO().FontGlobalScale = sx;
    ImGui::StyleColorsDark();
    install_input_callbacks(window);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    // Commands on standard input: read on their own thread, so the window never waits for a line. Detached: a
    // blocked read must not hold the exit.
    if (options.commands_on_stdin) {
        std::thread([&commands] {
            int n = 0;
            for (std::string line; std::getline(std::cin, line);) {
                try {
                    if (auto c = parse_command(line, "stdin:" + std::to_string(++n))) {
                        commands.push(*c);
                        glfwPostEmptyEvent();  // wakes an idle window at once
                    }
                } catch (const Error& e) {
                    say(std::string("error: ") + e.what());
                }
            }
        }).detach();
    }

    int status = app::kExitDone;
    {
        Viewer viewer(options, std::move(load), window);
        viewer.create_view();
        status = viewer.run(commands);
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    // The stdin thread may still be reading: leave without waiting for it.
    std::fflush(stdout);
    std::_Exit(status);
}

}  // namespace rtlab::view
