// Convergence of the path tracer: RMSE against an independent reference with 16 times the largest sample count
// falls as spp^-0.5 for unbiased Monte Carlo with independent samples. Renders a small scene built here (a
// floor, a glossy ball and a diffuse one, an emitting sphere, a point light and a uniform sky; 5 bounces) with
// the random pattern at 4, 16, 64, 256 and 1024 samples per pixel, and the reference at 16384 with another seed,
// then fits the log-log slope by least squares; each RMSE is over --runs renders of other seeds (default 8). Prints
// CSV (spp, rmse, seconds per render, largest pixel error) and the slope; exits 1 when the slope is outside
// -0.5 +- 0.05 (a benchmark, not a CI test: the reference alone takes a while).
//   rtlab_render_path_convergence [--size N] [--runs R]
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/render/render_job.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

std::shared_ptr<const Material> material(const std::string& name, Params p) {
    static const MaterialRegistry registry = make_material_registry();
    return registry.create(name, std::move(p));
}

RenderJob make_job(int size) {
    Params floor, ball, glossy, lamp;
    floor.set("albedo", 0.6);
    ball.set("albedo", Params::List{0.7, 0.3, 0.2});
    glossy.set("kd", 0.2).set("ks", 0.7).set("roughness", 0.3);
    lamp.set("albedo", 0.0).set("emission", 8.0);
    RenderJob job;
    job.camera = std::make_shared<PinholeCamera>(
        CameraSpec{.eye = {0, 1.4f, 4.5f}, .look_at = {0, 0.5f, 0}, .width = size, .height = size});
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
        {std::make_shared<Quad>(Point3(-3, 0, 3), Vec3(6, 0, 0), Vec3(0, 0, -6)),
         material("lambert", floor),
         {},
         "floor"},
        {std::make_shared<Sphere>(Point3(-0.7f, 0.6f, 0), 0.6f), material("cook-torrance", glossy), {}, "glossy"},
        {std::make_shared<Sphere>(Point3(0.8f, 0.5f, 0.3f), 0.5f), material("lambert", ball), {}, "ball"},
        {std::make_shared<Sphere>(Point3(1.0f, 2.0f, -1.0f), 0.3f), material("lambert", lamp), {}, "lamp"}});
    static const LightRegistry lights = make_light_registry();
    Params point;
    point.set("position", Params::List{-2, 4, 2}).set("intensity", 15.0);
    job.lights = {lights.create("point", point)};
    job.whitted.background = RGB(0.3f);
    job.integrator = IntegratorKind::path;
    job.path.max_depth = 5;
    job.settings.pattern = PixelPattern::random;
    return job;
}

}  // namespace

int main(int argc, char** argv) {
    int size = 24, runs = 8;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--size") == 0) size = std::max(1, std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--runs") == 0) runs = std::max(1, std::atoi(argv[i + 1]));
    }
    RenderJob job = make_job(size);
    job.settings.spp = 16384;
    job.settings.seed = 1000;
    const Image reference = render_job(job).image;
    std::printf("spp,rmse,seconds,largest_error\n");
    std::vector<double> xs, ys;
    for (int spp = 4; spp <= 1024; spp *= 4) {
        // The mean squared error over `runs` independent renders: the pixels the lamp's outline crosses carry most
        // of the error, and one render's few such pixels make its RMSE too noisy to fit a slope through.
        job.settings.spp = spp;
        double sum = 0.0, worst = 0.0, seconds = 0.0;
        for (int run = 0; run < runs; ++run) {
            job.settings.seed = static_cast<std::uint64_t>(spp) * 100 + static_cast<std::uint64_t>(run);
            const auto start = std::chrono::steady_clock::now();
            const Image image = render_job(job).image;
            seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            for (std::size_t k = 0; k < image.pixel_count(); ++k)
                for (int c = 0; c < 3; ++c) {
                    const double d = double(image.pixels()[k][c]) - double(reference.pixels()[k][c]);
                    sum += d * d;
                    worst = std::max(worst, std::abs(d));
                }
        }
        const double rmse = std::sqrt(sum / (3.0 * double(reference.pixel_count()) * runs));
        std::printf("%d,%.6g,%.3f,%.4g\n", spp, rmse, seconds / runs, worst);
        xs.push_back(std::log(double(spp)));
        ys.push_back(std::log(rmse));
    }
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < xs.size(); ++i) mx += xs[i] / xs.size(), my += ys[i] / ys.size();
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < xs.size(); ++i) sxy += (xs[i] - mx) * (ys[i] - my), sxx += (xs[i] - mx) * (xs[i] - mx);
    const double slope = sxy / sxx;
    std::printf("# log-log slope %.4f (expected -0.5 +- 0.05)\n", slope);
    return std::abs(slope + 0.5) <= 0.05 ? 0 : 1;
}
