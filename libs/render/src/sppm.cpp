#include "light_transport.hpp"
#include "tile_parallel.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/sppm.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>

namespace rtlab {

namespace {

using detail::GatherHit;
using detail::GatherPoint;

// Pixels per gather task: a row band, enough work per task, every pixel updated by its task alone.
constexpr int kGatherRows = 4;

// The smallest starting radius of a pixel without one given: this many pixel footprints at its first visible point.
constexpr float kFootprints = 1.0f;

// The visible point of one pixel in one iteration: what the gather reads.
struct VisiblePoint {
    std::uint32_t iteration = 0xffffffffu;  // the camera sample that made it; valid only for the current one
    Point3 position{0.0f};
    Frame frame;
    Vec3 wo_local{0.0f, 0.0f, 1.0f};
    SurfaceTerms terms;
    const Material* material = nullptr;
    RGB weight;  // beta / chance
    std::uint32_t bounce = 0;
    float distance = 0.0f;
};

// A pixel's progressive statistics.
struct PixelState {
    float radius = 0.0f;  // 0: no visible point yet
    double n = 0.0;
    std::array<double, 3> tau{};
};

// The angle one pixel spans at the image's centre: pixel footprints for the starting radii.
float pixel_angle(const Camera& camera) {
    const Vec2 c(0.5f * static_cast<float>(camera.width()), 0.5f * static_cast<float>(camera.height()));
    const Vec3 a = glm::normalize(camera.generate_ray(c, Vec2(0.5f)).direction);
    const Vec3 b = glm::normalize(camera.generate_ray(c + Vec2(1.0f, 0.0f), Vec2(0.5f)).direction);
    const float angle = std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
    return angle > 0.0f && std::isfinite(angle) ? angle : 1e-3f;
}

}  // namespace

/// The camera pass's radiance source: returns a sample's direct part and leaves its visible point in the pixel's
/// slot (each pixel's samples run on one thread at a time, in order, so no two writers share a slot).
class SppmCameraPass final : public StreamRadianceSource {
public:
    SppmCameraPass(const SceneQuery& scene, const LightSet& lights, const PathOptions& path, int width,
                   std::vector<VisiblePoint>& points)
        : m_scene(scene), m_lights(lights), m_path(path), m_width(width), m_points(points) {}

    RGB estimate(const Ray& ray, const SampleStream& stream, RayStats& stats) const override {
        std::optional<GatherPoint> gp;
        RGB L = detail::walk_to_gather_point(m_scene, m_lights, m_path, detail::WalkStart{ray}, stream, stats, gp);
        if (!gp) return L;
        GatherHit hit;
        L += detail::direct_at_gather_point(m_scene, m_lights, m_path, *gp, stream, stats, hit);
        const SampleKey& key = stream.key();
        VisiblePoint& p = m_points[static_cast<std::size_t>(key.y) * static_cast<std::size_t>(m_width) + key.x];
        p.iteration = key.sample;
        p.position = gp->v.hit.point;
        p.frame = gp->v.frame;
        p.wo_local = gp->v.wo_local;
        p.terms = gp->v.terms;
        p.material = gp->v.info.material;
        p.weight = gp->weight();
        p.bounce = gp->bounce;
        p.distance = gp->distance;
        return L;
    }

private:
    const SceneQuery& m_scene;
    const LightSet& m_lights;
    const PathOptions& m_path;
    int m_width;
    std::vector<VisiblePoint>& m_points;
};

struct SppmRenderer::State {
    State(const Camera& camera_, const SceneQuery& scene_, const LightSet& lights_, const SceneSphere& sphere_,
          PathOptions path_, PhotonOptions options_, const ProgressiveSettings& settings_)
        : camera(camera_),
          scene(scene_),
          lights(lights_),
          sphere(sphere_),
          path(std::move(path_)),
          options(options_),
          settings(settings_),
          points(static_cast<std::size_t>(camera_.width()) * static_cast<std::size_t>(camera_.height())),
          pixels(points.size()),
          source(scene_, lights_, path, camera_.width(), points),
          renderer(camera_, source, settings_),
          angle(pixel_angle(camera_)),
          max_radius(options_.max_radius > 0.0f ? options_.max_radius : sphere_.radius / 20.0f) {}

    const Camera& camera;
    const SceneQuery& scene;
    const LightSet& lights;
    SceneSphere sphere;
    PathOptions path;
    PhotonOptions options;
    ProgressiveSettings settings;
    std::vector<VisiblePoint> points;
    std::vector<PixelState> pixels;
    SppmCameraPass source;
    ProgressiveRenderer renderer;
    float angle;
    float max_radius;
    RayStats photon_rays;

    void gather(std::uint32_t iteration, const PhotonMap& map) {
        const int width = camera.width(), height = camera.height();
        const int bands = (height + kGatherRows - 1) / kGatherRows;
        detail::for_each_tile(settings.threads, bands, [&](int band) {
            for (int y = band * kGatherRows; y < std::min(height, (band + 1) * kGatherRows); ++y)
                for (int x = 0; x < width; ++x) {
                    const std::size_t i =
                        static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
                    if (points[i].iteration == iteration) update(points[i], pixels[i], map);
                }
        });
    }

    // A pixel's first radius: options.radius, else the distance to the nearest-th photon of its first iteration's
    // (PhotonOptions::nearest, as photon's estimates use), between a pixel footprint and the maximum radius: large
    // where photons are few, so that early iterations are not mostly noise; any start converges.
    float starting_radius(const VisiblePoint& vp, const PhotonMap& map) const {
        if (options.radius > 0.0f) return options.radius;
        const float footprint = kFootprints * angle * std::max(vp.distance, 1e-6f);
        const float largest = std::max(footprint, max_radius);
        thread_local std::vector<PointNeighbor> scratch;
        scratch.resize(static_cast<std::size_t>(options.nearest));
        const std::size_t n = map.tree().nearest(vp.position, largest * largest, scratch);
        if (n < scratch.size()) return largest;
        return std::clamp(std::sqrt(scratch[n - 1].distance2), footprint, largest);
    }

    void update(const VisiblePoint& vp, PixelState& px, const PhotonMap& map) const {
        if (px.radius == 0.0f) px.radius = starting_radius(vp, map);
        const long allowed = static_cast<long>(path.max_depth) - static_cast<long>(vp.bounce) - 1;
        if (allowed < 1) return;  // photons here have made a bounce: no path of them fits
        std::array<double, 3> phi{};
        std::uint64_t m = 0;
        const float r2 = px.radius * px.radius;
        map.tree().for_each_within(vp.position, r2, [&](std::uint32_t index, float) {
            const Photon& p = map.photons()[index];
            if (p.bounces > allowed) return;
            ++m;
            const RGB c =
                vp.material->eval(vp.terms, vp.wo_local, vp.frame.to_local(p.wi), TransportMode::radiance) * p.power;
            for (int k = 0; k < 3; ++k) phi[static_cast<std::size_t>(k)] += static_cast<double>(c[k]);
        });
        if (m == 0) return;
        const double n_new = px.n + static_cast<double>(options.alpha) * static_cast<double>(m);
        const double shrink2 = n_new / (px.n + static_cast<double>(m));  // r'^2 / r^2
        for (int k = 0; k < 3; ++k) {
            const auto c = static_cast<std::size_t>(k);
            px.tau[c] = (px.tau[c] + static_cast<double>(vp.weight[k]) * phi[c]) * shrink2;
        }
        px.n = n_new;
        px.radius = static_cast<float>(static_cast<double>(px.radius) * std::sqrt(shrink2));
    }
};

SppmRenderer::SppmRenderer(const Camera& camera, const SceneQuery& scene, const LightSet& lights,
                           const SceneSphere& sphere, PathOptions path, PhotonOptions options,
                           const ProgressiveSettings& settings) {
    check_photon_options(options);
    if (path.max_depth < 0) throw Error("sppm: max_depth must be >= 0");
    if (path.environment)
        throw Error("skybox: an environment texture sends no photons; photon mapping needs a 'background' colour");
    m_state = std::make_unique<State>(camera, scene, lights, sphere, std::move(path), options, settings);
}

SppmRenderer::~SppmRenderer() = default;

void SppmRenderer::plan_iterations(int iterations) { m_state->renderer.plan_passes(iterations); }

const SampleBuffer& SppmRenderer::direct() const { return m_state->renderer.buffer(); }

std::uint64_t SppmRenderer::photons_shot() const {
    return static_cast<std::uint64_t>(m_iterations) * m_state->options.photons;
}

float SppmRenderer::radius(int x, int y) const {
    return m_state
        ->pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(m_state->camera.width()) +
                 static_cast<std::size_t>(x)]
        .radius;
}

double SppmRenderer::photon_count(int x, int y) const {
    return m_state
        ->pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(m_state->camera.width()) +
                 static_cast<std::size_t>(x)]
        .n;
}

bool SppmRenderer::iterate(const ProgressiveCallbacks& callbacks) {
    State& s = *m_state;
    const auto start = std::chrono::steady_clock::now();
    const auto iteration = static_cast<std::uint32_t>(m_iterations);
    auto finish = [&](bool done) {
        m_stats.rays = s.renderer.stats().rays;
        m_stats.rays += RayCounters{s.photon_rays, 0};
        m_stats.tiles_done = s.renderer.stats().tiles_done;
        m_stats.tiles_total = s.renderer.stats().tiles_total;
        m_stats.cancelled = !done;
        m_stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return done;
    };
    if (!s.renderer.render_to(iteration + 1, callbacks, m_iterations)) return finish(false);
    PhotonTraceSettings trace;
    trace.photons = s.options.photons;
    trace.seed = s.settings.seed;
    trace.pass = iteration;
    trace.max_depth = s.path.max_depth;
    trace.roulette = s.path.roulette;
    trace.keep = kKeepCaustic | kKeepIndirect;
    trace.sequence = s.settings.sequence;
    trace.threads = s.settings.threads;
    PhotonTrace shot = trace_photons(s.scene, s.lights, s.sphere, trace, callbacks.stop);
    s.photon_rays += shot.rays;
    if (shot.cancelled) return finish(false);
    PhotonMap map;
    detail::run_on_threads(s.settings.threads, [&] { map = PhotonMap(std::move(shot.photons)); });
    s.gather(iteration, map);
    ++m_iterations;
    finish(true);
    if (callbacks.pass) callbacks.pass(PassUpdate{m_iterations - 1, iteration, iteration + 1, direct(), m_stats});
    return true;
}

Image SppmRenderer::image() const {
    const State& s = *m_state;
    const int width = s.camera.width(), height = s.camera.height();
    Image out(width, height);
    const double photons = static_cast<double>(photons_shot());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
            RGB c = direct().mean(x, y);
            const PixelState& p = s.pixels[i];
            if (p.radius > 0.0f && photons > 0.0) {
                const double d = photons * kPi * static_cast<double>(p.radius) * static_cast<double>(p.radius);
                c += RGB(static_cast<float>(p.tau[0] / d), static_cast<float>(p.tau[1] / d),
                         static_cast<float>(p.tau[2] / d));
            }
            out.at(x, y) = c;
        }
    return out;
}

RenderResult render_sppm(const Camera& camera, const SceneQuery& scene, const LightSet& lights,
                         const SceneSphere& sphere, const PathOptions& path, const PhotonOptions& options,
                         const RenderSettings& settings, const RenderCallbacks& callbacks) {
    if (settings.pattern != PixelPattern::sobol && settings.pattern != PixelPattern::random)
        throw Error("sppm: one camera sample per pixel per iteration: the pattern must be sobol or random, not " +
                    std::string(pixel_pattern_name(settings.pattern)) + " (add --aa sobol)");
    if (settings.spp < 1) throw Error("sppm: iterations (spp) must be >= 1, got " + std::to_string(settings.spp));
    ProgressiveSettings p;
    p.sequence = settings.pattern == PixelPattern::sobol ? SampleSequence::sobol : SampleSequence::independent;
    p.seed = settings.seed;
    p.tile_size = settings.tile_size;
    p.threads = settings.threads;
    SppmRenderer sppm(camera, scene, lights, sphere, path, options, p);
    sppm.plan_iterations(settings.spp);
    ProgressiveCallbacks cb;
    cb.progress = callbacks.progress;
    cb.stop = callbacks.stop;
    for (int i = 0; i < settings.spp; ++i)
        if (!sppm.iterate(cb)) break;
    RenderResult result;
    result.image = sppm.image();
    result.samples.assign(static_cast<std::size_t>(camera.width()) * static_cast<std::size_t>(camera.height()),
                          static_cast<std::uint32_t>(sppm.iterations()));
    result.stats = sppm.stats();
    return result;
}

}  // namespace rtlab
