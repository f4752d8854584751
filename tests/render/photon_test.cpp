// The photon tracer and the photon map: photon density against the irradiance a point light gives a plane; the power
// stored against the power emitted times the albedo of every bounce; the classification of photon paths; and the
// photon and sppm integrators' images the same bytes for any thread count.
#include "image_bytes.hpp"
#include "scene_fixtures.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/photon_integrator.hpp>
#include <rtlab/render/photon_tracer.hpp>
#include <rtlab/render/progressive.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sampled_lights.hpp>
#include <rtlab/render/sppm.hpp>
#include <rtlab/shading/environment_map.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstring>

using namespace rtlab;
using namespace rtlab::test;

namespace {

// Fewer photons under the sanitizers, where each costs ten times as much; the checks keep their meaning.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
constexpr std::uint32_t kScale = 4;
#else
constexpr std::uint32_t kScale = 1;
#endif

bool same_photons(const std::vector<Photon>& a, const std::vector<Photon>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Photon &p = a[i], &q = b[i];
        if (std::memcmp(&p.position, &q.position, sizeof(Point3)) != 0 ||
            std::memcmp(&p.wi, &q.wi, sizeof(Vec3)) != 0 || std::memcmp(&p.power, &q.power, sizeof(RGB)) != 0 ||
            p.bounces != q.bounces || p.path != q.path)
            return false;
    }
    return true;
}

std::shared_ptr<const Material> emitting(float radiance) {
    Params p;
    p.set("albedo", 0.0).set("emission", radiance);
    return material("lambert", p);
}

std::shared_ptr<const Material> rough_glass(float roughness) {
    Params p;
    p.set("roughness", roughness);
    return material("rough-dielectric", p);
}

// A scene and its lights as a sampling integrator sees them.
SampledLights sampled(std::vector<SceneObject> objects, std::vector<std::shared_ptr<const Light>> lights = {},
                      const RGB& background = {}) {
    WhittedOptions w;
    w.background = background;
    return make_sampled_lights(std::make_shared<Scene>(std::move(objects)), lights, w);
}

// Every kind of light and surface: a floor, a Lambert ball, smooth and rough glass, a mirror, an emitting sphere,
// a point light, an `area` light, a uniform sky.
RenderJob mixed_job(IntegratorKind kind) {
    RenderJob job;
    job.camera = std::make_shared<PinholeCamera>(
        CameraSpec{.eye = {0, 1.5f, 5}, .look_at = {0, 0.5f, 0}, .width = 16, .height = 16});
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
        {std::make_shared<Quad>(Point3(-3, 0, 3), Vec3(6, 0, 0), Vec3(0, 0, -6)), lambert(RGB(0.6f)), {}, "floor"},
        {std::make_shared<Sphere>(Point3(-1.0f, 0.5f, 0), 0.5f), material("glass"), {}, "glass"},
        {std::make_shared<Sphere>(Point3(0.2f, 0.4f, -0.5f), 0.4f), rough_glass(0.3f), {}, "frosted"},
        {std::make_shared<Sphere>(Point3(1.1f, 0.4f, 0.3f), 0.4f), lambert(RGB(0.7f, 0.4f, 0.2f)), {}, "ball"},
        {std::make_shared<Quad>(Point3(-2, 0, -1.5f), Vec3(4, 0, 0), Vec3(0, 1.5f, 0)),
         material("mirror"),
         {},
         "mirror"},
        {std::make_shared<Sphere>(Point3(0.8f, 1.8f, -0.5f), 0.2f), emitting(8.0f), {}, "lamp"}});
    Params area;
    area.set("corner", list(Vec3(-1.5f, 3, -1))).set("edge_u", list(Vec3(1, 0, 0))).set("edge_v", list(Vec3(0, 0, 1)));
    area.set("intensity", 3.0f);
    job.lights = {point_light(Point3(-2, 3, 2), 15.0f), light("area", area)};
    job.whitted.background = RGB(0.1f);
    job.integrator = kind;
    job.path.max_depth = 6;
    job.photons.photons = 4000;
    job.photons.nearest = 20;
    job.settings.pattern = PixelPattern::sobol;
    job.settings.spp = 4;
    job.settings.seed = 7;
    return job;
}

// A glass ball of radius 0.4 floating over a diffuse floor, seen from above (16 x 16), with `lights` added: the
// scene of the tests that photon and sppm count no light twice; path depth 6, sobol, 2 threads.
RenderJob glass_ball_job(std::vector<SceneObject> lights, unsigned seed) {
    std::vector<SceneObject> objects{
        {std::make_shared<Quad>(Point3(-2, 0, 2), Vec3(4, 0, 0), Vec3(0, 0, -4)), lambert(RGB(0.8f)), {}, "floor"},
        {std::make_shared<Sphere>(Point3(0.0f, 0.9f, 0), 0.4f), material("glass"), {}, "glass"}};
    for (SceneObject& l : lights) objects.push_back(std::move(l));
    RenderJob job;
    job.camera = std::make_shared<PinholeCamera>(CameraSpec{
        .eye = {0, 2.0f, 1.6f}, .look_at = {0, 0.0f, 0}, .vertical_fov_degrees = 40.0f, .width = 16, .height = 16});
    job.scene = std::make_shared<Scene>(std::move(objects));
    job.path.max_depth = 6;
    job.settings.pattern = PixelPattern::sobol;
    job.settings.seed = seed;
    job.settings.threads = 2;
    return job;
}

// The image's mean channel value and its standard error (from the per-pixel variances of a progressive render).
std::pair<double, double> mean_of(const RenderResult& r) {
    double sum = 0.0, variance = 0.0;
    for (const RGB& c : r.image.pixels()) sum += channel_mean(c);
    if (r.buffer)
        for (int y = 0; y < r.image.height(); ++y)
            for (int x = 0; x < r.image.width(); ++x) variance += channel_mean(r.buffer->mean_variance(x, y));
    const auto n = static_cast<double>(r.image.pixel_count());
    return {sum / n, std::sqrt(variance) / n};
}

}  // namespace

TEST_CASE("photons are the same for any thread count and kept in index order", "[photon]") {
    const RenderJob job = mixed_job(IntegratorKind::photon);
    const SampledLights s = make_sampled_lights(job.scene, job.lights, job.whitted);
    PhotonTraceSettings settings;
    settings.photons = 6000 / kScale;
    settings.seed = 3;
    settings.threads = 1;
    const PhotonTrace one = trace_photons(*s.scene, s.lights, s.sphere, settings);
    settings.threads = 2;
    const PhotonTrace two = trace_photons(*s.scene, s.lights, s.sphere, settings);
    REQUIRE(one.photons.size() > settings.photons / 10);
    CHECK(same_photons(one.photons, two.photons));
    CHECK(one.shot == settings.photons);
    CHECK(one.rays.reflected == two.rays.reflected);
    CHECK(one.rays.refracted == two.rays.refracted);
    // Another pass is another set of photons.
    settings.pass = 1;
    CHECK(!same_photons(trace_photons(*s.scene, s.lights, s.sphere, settings).photons, one.photons));
}

TEST_CASE("photon density under a point light gives the irradiance on a plane", "[photon]") {
    // A point light of intensity I at height h over a plane: E(d) = I h / (h^2 + d^2)^(3/2) at distance d from the
    // foot of the light. The estimate from the k nearest photons (box kernel) has a relative standard error of at
    // most 1/sqrt(k) (Poisson counts; Sobol photons are more even), here 4.5%: each point is checked at 4 of them,
    // plus 1% for the curvature of E over the disk, a family of 5 points at p < 3e-4.
    const float intensity = 2.0f, h = 1.0f;
    const SampledLights s = sampled({{std::make_shared<Quad>(Point3(-20, 0, 20), Vec3(40, 0, 0), Vec3(0, 0, -40)),
                                      lambert(RGB(0.5f)),
                                      {},
                                      "plane"}},
                                    {point_light(Point3(0, h, 0), intensity)});
    PhotonTraceSettings settings;
    settings.photons = 400000 / kScale;
    settings.max_depth = 1;
    settings.keep = kKeepDirect;
    const PhotonTrace trace = trace_photons(*s.scene, s.lights, s.sphere, settings);
    // The photons that meet the plane: its solid angle, 4 atan(a^2 / (h sqrt(2 a^2 + h^2))) for half-side a, of 4 pi.
    const double a = 20.0;
    const double share = std::atan(a * a / (h * std::sqrt(2.0 * a * a + h * h))) / kPi;
    CHECK(static_cast<double>(trace.photons.size()) == Approx(settings.photons * share).epsilon(0.005));
    const PhotonMap map(trace.photons);
    const int k = 500 / static_cast<int>(kScale);
    std::vector<PointNeighbor> scratch(static_cast<std::size_t>(k));
    for (const float d : {0.0f, 0.3f, 0.7f, 1.2f, 2.0f}) {
        const Point3 x(d * 0.6f, 0.0f, d * 0.8f);
        const RGB e = map.estimate(x, 1e30f, PhotonFilter::box, scratch, [](const Photon& p) { return p.power; }) *
                      (1.0f / static_cast<float>(trace.shot));
        const double expected = intensity * h / std::pow(h * h + d * d, 1.5);
        INFO("d " << d << ": estimate " << e.r << ", expected " << expected);
        CHECK(std::abs(e.r - expected) <= expected * (4.0 / std::sqrt(k) + 0.01));
        CHECK(e.r == e.b);  // a grey light
    }
}

TEST_CASE("the power stored is the power emitted times the albedo of every bounce", "[photon]") {
    // A point light inside a closed sphere of albedo rho (its inside facing in): every photon meets the sphere at
    // every bounce, and Lambert's sampled value is rho exactly, so without roulette the power stored at bounce b is
    // Phi rho^b per photon shot, to rounding. With roulette it is so in expectation.
    const float rho = 0.6f, intensity = 1.5f;
    const SampledLights s =
        sampled({{std::make_shared<Sphere>(Point3(0.0f), 1.0f), lambert(RGB(rho)), {true, true}, "inside"}},
                {point_light(Point3(0.1f, -0.2f, 0.3f), intensity)});
    const double phi = 4.0 * kPi * intensity;
    PhotonTraceSettings settings;
    settings.photons = 20000 / kScale;
    settings.max_depth = 5;
    auto sums = [&](const PhotonTrace& t) {
        std::vector<double> sum(5, 0.0);
        for (const Photon& p : t.photons) sum[p.bounces] += p.power.g;
        return sum;
    };
    SECTION("without roulette: exactly") {
        settings.roulette = false;
        const PhotonTrace t = trace_photons(*s.scene, s.lights, s.sphere, settings);
        CHECK(t.photons.size() >= 5u * settings.photons - 5u);  // a draw at the horizon may end a path
        const std::vector<double> sum = sums(t);
        for (int b = 0; b < 5; ++b) {
            INFO("bounce " << b);
            CHECK(sum[static_cast<std::size_t>(b)] / t.shot == Approx(phi * std::pow(rho, b)).epsilon(1e-4));
        }
    }
    SECTION("with roulette: in expectation") {
        // Survival rho at every bounce and the survivors' power divided by it: each photon stored at bounce b
        // carries Phi, found with probability rho^b; the count of survivors is binomial.
        settings.roulette = true;
        const PhotonTrace t = trace_photons(*s.scene, s.lights, s.sphere, settings);
        const std::vector<double> sum = sums(t);
        for (int b = 0; b < 5; ++b) {
            const double p = std::pow(rho, b), n = t.shot;
            const double se = phi * std::sqrt(p * (1.0 - p) / n);
            INFO("bounce " << b << ": " << sum[static_cast<std::size_t>(b)] / n << " expected " << phi * p << " +- "
                           << se);
            CHECK(std::abs(sum[static_cast<std::size_t>(b)] / n - phi * p) <= 4.0 * se + 1e-6 * phi);
        }
    }
    SECTION("an area light and a point light chosen by power") {
        // An emitting sphere inside too (one-sided, outwards): the power reaching the first bounce is both lights'.
        const SampledLights two =
            sampled({{std::make_shared<Sphere>(Point3(0.0f), 1.0f), lambert(RGB(rho)), {true, true}, "inside"},
                     {std::make_shared<Sphere>(Point3(-0.6f, 0.0f, 0.0f), 0.05f), emitting(40.0f), {}, "lamp"}},
                    {point_light(Point3(0.6f, 0.0f, 0.0f), intensity)});
        settings.roulette = false;
        settings.max_depth = 1;
        const PhotonTrace t = trace_photons(*two.scene, two.lights, two.sphere, settings);
        double total = 0.0;
        for (const Photon& p : t.photons) total += p.power.g;
        const double expected = phi + 40.0 * kPi * 4.0 * kPi * 0.0025;
        // The light choice is by Sobol numbers: the share of each light is exact to 1 / photons. (The lamp shades
        // 0.04% of the point light's photons.)
        CHECK(total / t.shot == Approx(expected).epsilon(5e-3));
    }
}

TEST_CASE("photon paths are classed by their events and stored on diffuse surfaces only", "[photon]") {
    // A point light under a mirror ceiling, a rough glass ball and a diffuse floor: photons reach the floor straight
    // (direct), off the mirror or through the glass alone (caustic: pass-through events), or after the floor
    // (indirect). None is stored on the mirror or the glass.
    const SampledLights s = sampled(
        {{std::make_shared<Quad>(Point3(-5, 0, 5), Vec3(10, 0, 0), Vec3(0, 0, -10)), lambert(RGB(0.8f)), {}, "floor"},
         {std::make_shared<Quad>(Point3(-5, 3, -5), Vec3(10, 0, 0), Vec3(0, 0, 10)), material("mirror"), {}, "mirror"},
         {std::make_shared<Sphere>(Point3(0.5f, 0.6f, 0.0f), 0.6f), rough_glass(0.2f), {}, "ball"}},
        {point_light(Point3(0, 2.5f, 0.5f), 10.0f)});
    PhotonTraceSettings settings;
    settings.photons = 20000 / kScale;
    const PhotonTrace t = trace_photons(*s.scene, s.lights, s.sphere, settings);
    int counts[3] = {0, 0, 0};
    bool on_floor = true, bounces_fit = true;
    for (const Photon& p : t.photons) {
        ++counts[static_cast<int>(p.path)];
        on_floor = on_floor && std::abs(p.position.y) < 1e-4f;
        if (p.path == PhotonPath::direct) bounces_fit = bounces_fit && p.bounces == 0;
        if (p.path == PhotonPath::caustic) bounces_fit = bounces_fit && p.bounces >= 1;
        // The floor is flat: a diffuse event there, then at least one more to come back to it.
        if (p.path == PhotonPath::indirect) bounces_fit = bounces_fit && p.bounces >= 2;
    }
    INFO("direct " << counts[0] << ", caustic " << counts[1] << ", indirect " << counts[2]);
    CHECK(on_floor);
    CHECK(bounces_fit);
    CHECK(counts[0] > 1000 / static_cast<int>(kScale));
    CHECK(counts[1] > 1000 / static_cast<int>(kScale));
    CHECK(counts[2] > 500 / static_cast<int>(kScale));
}

TEST_CASE("photon and sppm images are the same bytes on 1 and 2 threads", "[photon]") {
    for (const IntegratorKind kind : {IntegratorKind::photon, IntegratorKind::sppm}) {
        for (const int gather : {0, 2}) {
            if (kind == IntegratorKind::sppm && gather > 0) continue;
            RenderJob job = mixed_job(kind);
            job.photons.gather = gather;
            job.settings.threads = 1;
            const RenderResult one = render_job(job);
            job.settings.threads = 2;
            const RenderResult two = render_job(job);
            INFO(integrator_name(kind) << ", gather " << gather);
            CHECK(same_bytes(one.image, two.image));
            CHECK(one.stats.rays == two.stats.rays);
            double sum = 0.0;
            for (const RGB& c : one.image.pixels()) sum += channel_mean(c);
            CHECK(sum / static_cast<double>(one.image.pixel_count()) > 0.05);
        }
    }
}

TEST_CASE("sppm iterations resumed after a stop give the same image", "[photon]") {
    // A stop seen in an iteration leaves nothing of it counted; asking again finishes it as if never stopped.
    const RenderJob job = mixed_job(IntegratorKind::sppm);
    const SampledLights s = make_sampled_lights(job.scene, job.lights, job.whitted);
    ProgressiveSettings settings;
    settings.seed = 5;
    settings.threads = 2;
    SppmRenderer plain(*job.camera, *s.scene, s.lights, s.sphere, job.path, job.photons, settings);
    SppmRenderer stopped(*job.camera, *s.scene, s.lights, s.sphere, job.path, job.photons, settings);
    for (int i = 0; i < 3; ++i) REQUIRE(plain.iterate());
    std::atomic<bool> stop{true};
    ProgressiveCallbacks cb;
    cb.stop = &stop;
    REQUIRE(stopped.iterate());
    CHECK(!stopped.iterate(cb));
    CHECK(stopped.iterations() == 1);
    REQUIRE(stopped.iterate());
    REQUIRE(stopped.iterate());
    CHECK(same_bytes(plain.image(), stopped.image()));
    CHECK(plain.photons_shot() == 3u * job.photons.photons);
}

TEST_CASE("photon mapping settings and scenes it cannot honour are errors naming them", "[photon]") {
    RenderJob job = mixed_job(IntegratorKind::photon);
    job.photons.nearest = 0;
    CHECK_THROWS_WITH(render_job(job), Catch::Contains("nearest"));
    job = mixed_job(IntegratorKind::sppm);
    job.photons.alpha = 1.0f;
    CHECK_THROWS_WITH(render_job(job), Catch::Contains("alpha"));
    job = mixed_job(IntegratorKind::sppm);
    job.settings.pattern = PixelPattern::jittered;
    CHECK_THROWS_WITH(render_job(job), Catch::Contains("sobol or random"));
    job = mixed_job(IntegratorKind::photon);
    job.whitted.environment = make_constant_texture(RGB(1.0f));
    CHECK_THROWS_WITH(render_job(job), Catch::Contains("skybox"));
    CHECK(parse_integrator("sppm") == IntegratorKind::sppm);
    CHECK(integrator_name(IntegratorKind::photon) == "photon");
}

TEST_CASE("photon and sppm count no light twice: the caustic under a glass ball", "[photon]") {
    // A glass ball floats over a floor under a square lamp: the floor in view gets direct light (next-event
    // estimation), the caustic (the caustic map, or sppm's photons) and a little indirect light (the global map or
    // final gather). The image means must agree with the path tracer's, within its 3 standard errors plus 4% for the
    // photon map's blur; the light through the glass is about 40% of the image (what `direct` misses), so counting a
    // part twice or missing it shows. Measured: path 0.0482 +- 0.0003 at 4096 spp, photon 0.0491 with 50000 photons
    // and 0.0484 with a million (the density estimate's bias), sppm 0.0483.
    RenderJob job =
        glass_ball_job({{std::make_shared<Quad>(Point3(-0.3f, 2.6f, -0.3f), Vec3(0.6f, 0, 0), Vec3(0, 0, 0.6f)),
                         emitting(5.0f),
                         {},
                         "lamp"}},
                       9);
    job.integrator = IntegratorKind::path;
    job.settings.spp = 1024 / static_cast<int>(kScale);
    const auto [path, se] = mean_of(render_job(job));
    job.integrator = IntegratorKind::direct;
    job.settings.spp = 256 / static_cast<int>(kScale);
    const double direct = mean_of(render_job(job)).first;
    INFO("path " << path << " +- " << se << ", direct " << direct);
    REQUIRE(path - direct > 0.3 * path);
    auto check = [&](const char* what, double mean) {
        INFO(what << ": " << mean);
        CHECK(std::abs(mean - path) <= 3.0 * se + 0.04 * path);
    };
    job.integrator = IntegratorKind::photon;
    job.photons.photons = 100000 / kScale;
    job.settings.spp = 8;
    job.photons.gather = 0;
    check("photon without final gather", mean_of(render_job(job)).first);
    job.photons.gather = 1;
    check("photon with final gather", mean_of(render_job(job)).first);
    job.integrator = IntegratorKind::sppm;
    job.photons.photons = 20000 / kScale;
    job.settings.spp = 16;
    check("sppm", mean_of(render_job(job)).first);
}

TEST_CASE("photon and sppm under an environment map: its photons make the caustic the path tracer sees", "[photon]") {
    // The glass ball over a floor again, now lit by an environment map alone: a dim sky and a bright sun high up
    // (two texels of a 16 x 8 map), so the caustic comes from photons the map sends (EnvironmentEmitter::sample_le)
    // and the direct light from sampling it. The means must agree with the path tracer's as in the test above.
    // Measured: path 1.820 +- 0.005, direct 1.403 (the light through the glass and off the floor is 23%), photon
    // 1.813, sppm 1.814.
    Image sky(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) sky.at(x, y) = y < 4 ? RGB(0.15f, 0.2f, 0.3f) : RGB(0.05f);
    sky.at(7, 1) = sky.at(8, 1) = RGB(60.0f, 55.0f, 45.0f);
    RenderJob job = glass_ball_job({}, 11);
    job.environment = std::make_shared<EnvironmentMap>(std::move(sky));
    job.integrator = IntegratorKind::path;
    job.settings.spp = 1024 / static_cast<int>(kScale);
    const auto [path, se] = mean_of(render_job(job));
    job.integrator = IntegratorKind::direct;
    job.settings.spp = 256 / static_cast<int>(kScale);
    const double direct = mean_of(render_job(job)).first;
    INFO("path " << path << " +- " << se << ", direct " << direct);
    REQUIRE(path - direct > 0.15 * path);
    auto check = [&](const char* what, double mean) {
        INFO(what << ": " << mean);
        CHECK(std::abs(mean - path) <= 3.0 * se + 0.04 * path);
    };
    job.integrator = IntegratorKind::photon;
    job.photons.photons = 100000 / kScale;
    job.settings.spp = 8;
    check("photon", mean_of(render_job(job)).first);
    job.integrator = IntegratorKind::sppm;
    job.photons.photons = 20000 / kScale;
    job.settings.spp = 16;
    check("sppm", mean_of(render_job(job)).first);
}

TEST_CASE("make_radiance_source and make_sppm_renderer render what render_job does", "[photon]") {
    // The one way every program builds an integrator from a job: rtlab-render's noise target and shares and the
    // viewer render progressively through these, and must see render_job's image.
    RenderJob job = mixed_job(IntegratorKind::photon);
    job.settings.threads = 2;
    const Image expected = render_job(job).image;
    ProgressiveSettings p;
    p.sequence = SampleSequence::sobol;
    p.spp = job.settings.spp;
    p.seed = job.settings.seed;
    p.threads = 2;
    const auto source = make_radiance_source(job, IntegratorKind::photon);
    CHECK(same_bytes(render_progressive(*job.camera, *source, p).image, expected));
    job.integrator = IntegratorKind::sppm;
    const Image sppm_expected = render_job(job).image;
    const auto sppm = make_sppm_renderer(job, *job.camera, p);
    for (int i = 0; i < job.settings.spp; ++i) REQUIRE(sppm->iterate());
    CHECK(same_bytes(sppm->image(), sppm_expected));
    CHECK_THROWS_WITH(make_radiance_source(job, IntegratorKind::sppm), Catch::Contains("make_sppm_renderer"));
    // A stop flag already set while the photons are shot: the maps stay empty, and the flag says so.
    const std::atomic<bool> stop{true};
    const auto stopped = std::dynamic_pointer_cast<const PhotonIntegrator>(
        make_radiance_source(mixed_job(IntegratorKind::photon), IntegratorKind::photon, &stop));
    REQUIRE(stopped);
    CHECK(stopped->cancelled());
    CHECK(stopped->global_map().size() == 0);
}
