// The direct and path integrators end to end through render_job(): each check a number with its standard error
// (the spread of the pixel means, every pixel being an independent estimate of the same quantity), on small
// images with few samples and fixed seeds.
#include "image_bytes.hpp"
#include "scene_fixtures.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sampled_lights.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

using namespace rtlab;
using namespace rtlab::test;

namespace {

struct PixelStats {
    double mean = 0.0, standard_error = 0.0, max = 0.0;
};

// Channel means of the pixels, their mean, its standard error and the largest.
PixelStats pixel_stats(const Image& image) {
    double sum = 0.0, sum2 = 0.0, max = 0.0;
    const auto n = static_cast<double>(image.pixel_count());
    for (const RGB& c : image.pixels()) {
        const double v = channel_mean(c);
        sum += v;
        sum2 += v * v;
        max = std::max(max, double(c.max_component()));
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1.0)), max};
}

std::shared_ptr<const Material> lambert_emitting(float albedo, float emission) {
    Params p;
    p.set("albedo", albedo).set("emission", emission);
    return material("lambert", p);
}

RenderJob sampled_job(IntegratorKind kind, int size, int spp, CameraSpec camera) {
    RenderJob job;
    camera.width = camera.height = size;
    job.camera = std::make_shared<PinholeCamera>(camera);
    job.integrator = kind;
    job.settings.pattern = PixelPattern::sobol;
    job.settings.spp = spp;
    job.settings.seed = 3;
    return job;
}

// A small scene of every kind of light: a floor, a glossy ball, an emitting sphere, a point light, an `area`
// light (an emitting quad under these integrators) and a uniform environment.
RenderJob mixed_job(IntegratorKind kind) {
    RenderJob job = sampled_job(kind, 16, 8, CameraSpec{.eye = {0, 1.5f, 5}, .look_at = {0, 0.5f, 0}});
    Params ct;
    ct.set("kd", 0.3f).set("ks", 0.6f).set("roughness", 0.4f);
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
        {std::make_shared<Quad>(Point3(-3, 0, 3), Vec3(6, 0, 0), Vec3(0, 0, -6)), lambert(RGB(0.6f)), {}, "floor"},
        {std::make_shared<Sphere>(Point3(-0.6f, 0.7f, 0), 0.7f), material("cook-torrance", ct), {}, "ball"},
        {std::make_shared<Sphere>(Point3(1.2f, 1.8f, -0.5f), 0.3f), lambert_emitting(0.0f, 6.0f), {}, "lamp"}});
    Params area;
    area.set("corner", list(Vec3(-1, 3, -1))).set("edge_u", list(Vec3(0, 0, 1))).set("edge_v", list(Vec3(1, 0, 0)));
    area.set("intensity", 3.0f);
    job.lights = {point_light(Point3(2, 4, 3), 20.0f), light("area", area)};
    job.whitted.background = RGB(0.2f);
    return job;
}

}  // namespace

TEST_CASE("furnace: albedo-1 objects in a uniform environment of radiance 1 vanish", "[path]") {
    // Two-sided Lambert surfaces of albedo 1 inside radiance 1: every path carries 1 back whatever it meets,
    // so the image is 1 but for noise (Russian roulette keeps paths finite, survival capped at 0.95).
    RenderJob job = sampled_job(IntegratorKind::path, 20, 16, CameraSpec{.eye = {0, 0.5f, 4}, .look_at = {0, 0, 0}});
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
        {std::make_shared<Sphere>(Point3(0.0f), 1.0f), lambert(RGB(1.0f)), {}, "ball"},
        {std::make_shared<Quad>(Point3(-2, -1, 2), Vec3(4, 0, 0), Vec3(0, 0, -4)), lambert(RGB(1.0f)), {}, "floor"}});
    job.whitted.background = RGB(1.0f);
    job.path.max_depth = 100;
    const PixelStats s = pixel_stats(render_job(job).image);
    INFO("mean " << s.mean << " +- " << s.standard_error << ", max " << s.max);
    CHECK(std::abs(s.mean - 1.0) <= 3.0 * s.standard_error);
    CHECK(s.standard_error > 0.0);
    CHECK(s.max <= 5.0);
}

TEST_CASE("a closed emitting sphere seen from inside gives the geometric series", "[path]") {
    // Albedo rho, emission Le inward, camera inside: each bounce adds rho^k Le, so L = Le (1 - rho^(d+1)) / (1 - rho)
    // at max depth d and Le / (1 - rho) without a limit.
    const float rho = 0.5f, le = 1.0f;
    RenderJob job = sampled_job(IntegratorKind::path, 8, 64, CameraSpec{.eye = {0.2f, 0, 0.1f}, .look_at = {0, 0, -1}});
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
        {std::make_shared<Sphere>(Point3(0.0f), 1.0f), lambert_emitting(rho, le), {true, true}, "shell"}});
    SECTION("at max depth 3 without roulette") {
        job.path.max_depth = 3;
        job.path.roulette = false;
        const PixelStats s = pixel_stats(render_job(job).image);
        const double expected = le * (1.0 - std::pow(rho, 4.0)) / (1.0 - rho);
        INFO("mean " << s.mean << " +- " << s.standard_error << ", expected " << expected);
        CHECK(std::abs(s.mean - expected) <= 3.0 * s.standard_error + 1e-6);
    }
    SECTION("with roulette and no limit to speak of") {
        job.path.max_depth = 100;
        job.path.roulette_depth = 1;
        const PixelStats s = pixel_stats(render_job(job).image);
        const double expected = le / (1.0 - rho);
        INFO("mean " << s.mean << " +- " << s.standard_error << ", expected " << expected);
        CHECK(std::abs(s.mean - expected) <= 3.0 * s.standard_error);
        CHECK(s.standard_error > 0.0);
    }
    SECTION("max depth 0 sees the emission alone") {
        job.path.max_depth = 0;
        const PixelStats s = pixel_stats(render_job(job).image);
        CHECK(s.mean == Approx(le));
    }
}

TEST_CASE("path at depth 1 is direct byte for byte", "[path]") {
    RenderJob direct = mixed_job(IntegratorKind::direct);
    RenderJob path = mixed_job(IntegratorKind::path);
    path.path.max_depth = 1;
    const Image a = render_job(direct).image, b = render_job(path).image;
    CHECK(pixel_stats(a).mean > 0.05);
    CHECK(same_bytes(a, b));
    path.path.max_depth = 2;  // the comparison can fail: one more bounce adds light
    CHECK(pixel_stats(render_job(path).image).mean > pixel_stats(a).mean);
}

TEST_CASE("direct agrees with whitted in the physical convention under point lights", "[path]") {
    // Opaque materials, point lights, no emitters: both compute f cos I / r^2 per light at the pixel centres
    // (PixelPattern::none), where the BSDF sample of direct meets no light.
    RenderJob job;
    job.camera = std::make_shared<PinholeCamera>(
        CameraSpec{.eye = {0, 1, 5}, .look_at = {0, 0.3f, 0}, .width = 24, .height = 24});
    Params bp;
    bp.set("kd", 0.4f).set("ks", 0.3f).set("exponent", 30.0f);
    Params ct;
    ct.set("kd", 0.2f).set("ks", 0.7f).set("roughness", 0.5f);
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
        {std::make_shared<Quad>(Point3(-3, 0, 3), Vec3(6, 0, 0), Vec3(0, 0, -6)), lambert(RGB(0.7f)), {}, "floor"},
        {std::make_shared<Sphere>(Point3(-0.7f, 0.6f, 0), 0.6f), material("blinn-phong", bp), {}, "a"},
        {std::make_shared<Sphere>(Point3(0.8f, 0.5f, 0.3f), 0.5f), material("cook-torrance", ct), {}, "b"}});
    job.lights = {point_light(Point3(2, 4, 3), 30.0f), point_light(Point3(-3, 2, 1), 10.0f)};
    const Image whitted = render_job(job).image;
    job.integrator = IntegratorKind::direct;
    const Image direct = render_job(job).image;
    double worst = 0.0, total = 0.0;
    for (std::size_t i = 0; i < whitted.pixel_count(); ++i) {
        const RGB a = whitted.pixels()[i], b = direct.pixels()[i];
        worst = std::max(worst, double((a - b).max_component() + (b - a).max_component()) / (1e-3 + a.max_component()));
        total += channel_mean(a);
    }
    INFO("largest relative difference " << worst);
    CHECK(total > 1.0);
    CHECK(worst < 1e-4);
}

TEST_CASE("what the sampling integrators cannot honour physically is an error naming it", "[path]") {
    RenderJob job = mixed_job(IntegratorKind::path);
    job.whitted.convention = Convention::classic;
    CHECK_THROWS_WITH(render_job(job), Catch::Contains("convention"));
    job = mixed_job(IntegratorKind::direct);
    Params ambient;
    ambient.set("intensity", 0.2f);
    job.lights.push_back(light("ambient", ambient));
    CHECK_THROWS_WITH(render_job(job), Catch::Contains("ambient"));
}

TEST_CASE("an area light under direct gives what whitted's area light gives", "[path]") {
    // The same rectangle: Whitted samples it n x n as point lights, direct as an emitting quad with MIS; both
    // estimate the same direct light, so the image means agree within their noise.
    // The camera stays below the light, which the direct integrator shows and Whitted's does not.
    RenderJob job = sampled_job(IntegratorKind::direct, 16, 64, CameraSpec{.eye = {0, 1, 4}, .look_at = {0, -1, 0}});
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
        {std::make_shared<Quad>(Point3(-2, 0, 2), Vec3(4, 0, 0), Vec3(0, 0, -4)), lambert(RGB(0.8f)), {}, "floor"}});
    Params area;
    area.set("corner", list(Vec3(-0.5f, 1.5f, -0.5f))).set("edge_u", list(Vec3(1, 0, 0)));  // faces down
    area.set("edge_v", list(Vec3(0, 0, 1))).set("intensity", 4.0f).set("samples", 8.0);
    job.lights = {light("area", area)};
    const PixelStats d = pixel_stats(render_job(job).image);
    job.integrator = IntegratorKind::whitted;
    const PixelStats w = pixel_stats(render_job(job).image);
    INFO("direct " << d.mean << " +- " << d.standard_error << ", whitted " << w.mean << " +- " << w.standard_error);
    CHECK(d.mean > 0.05);
    // The pixel spread is mostly the image's own variation, shared by both: a generous but finite bound.
    CHECK(std::abs(d.mean - w.mean) <= 0.01 * w.mean);
}
