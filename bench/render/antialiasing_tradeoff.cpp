// Anti-aliasing: render time against RMSE to a high-sample reference, for every pixel pattern at increasing
// sample counts and for adaptive supersampling at several thresholds, on two scenes built here:
//   checker  a high-contrast checkerboard plane (radiance 1 and 0.02) to the horizon under a grey sky,
//            evaluated analytically (no geometry), so the time is the sampling's own;
//   whitted  a Whitted-like scene through RenderJob: a checker-textured floor, a mirror and a glass sphere,
//            two point lights.
// The reference is the jittered pattern at 400 samples per pixel with another seed. RMSE is over the linear
// RGB values clamped to [0, 1] (what a display shows before encoding), all pixels and channels.
// Each configuration is rendered `--runs` times (default 3) on one thread; the time is the median wall time.
// Writes CSV to the file given as the first argument (stdout without one).
//   rtlab_render_aa_tradeoff docs/data/antialiasing.csv [--runs N] [--width W] [--images DIR]
// --images writes each scene's reference and its 1-sample render as PNG into DIR, to look at.
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/textures/texture.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

std::shared_ptr<const Material> material(const std::string& name, Params p = {}) {
    static const MaterialRegistry registry = make_material_registry();
    return registry.create(name, std::move(p));
}

std::shared_ptr<const Light> point_light(const Point3& at, float intensity) {
    static const LightRegistry registry = make_light_registry();
    Params p;
    p.set("position", Params::List{at.x, at.y, at.z}).set("intensity", intensity);
    return registry.create("point", p);
}

/// Radiance of the checker scene: the plane y = -1 with unit tiles, 1 and 0.02, under a sky of 0.3.
RGB checker_radiance(const Ray& ray) {
    if (ray.direction.y >= 0.0f) return RGB(0.3f);
    const float t = (-1.0f - ray.origin.y) / ray.direction.y;
    const double x = ray.origin.x + t * ray.direction.x, z = ray.origin.z + t * ray.direction.z;
    const bool odd = (static_cast<long long>(std::floor(x)) + static_cast<long long>(std::floor(z))) & 1;
    return RGB(odd ? 1.0f : 0.02f);
}

RenderJob whitted_job(int width, int height) {
    static const TextureRegistry textures = make_texture_registry();
    Params checker;
    checker.set("tiles_u", 100.0f)
        .set("color1", Params::List{0.9f, 0.9f, 0.9f})
        .set("color2", Params::List{0.05f, 0.05f, 0.3f});
    Params floor;
    floor.set_object<Texture>("albedo", textures.create("checker", checker));
    std::vector<SceneObject> objects{
        {std::make_shared<Quad>(Point3(-50, 0, 20), Vec3(100, 0, 0), Vec3(0, 0, -100)),
         material("lambert", floor),
         {},
         "floor"},
        {std::make_shared<Sphere>(Point3(-1.2f, 1.0f, -6.0f), 1.0f), material("mirror"), {}, "mirror"},
        {std::make_shared<Sphere>(Point3(1.3f, 0.9f, -4.5f), 0.9f), material("glass"), {}, "glass"}};
    RenderJob job;
    job.scene = std::make_shared<Scene>(std::move(objects));
    job.camera = std::make_shared<PinholeCamera>(CameraSpec{.eye = {0, 1.6f, 2},
                                                            .look_at = {0, 0.8f, -6},
                                                            .vertical_fov_degrees = 45.0f,
                                                            .width = width,
                                                            .height = height});
    job.lights = {point_light(Point3(-4, 8, 0), 150.0f), point_light(Point3(5, 6, -3), 60.0f)};
    job.whitted.background = RGB(0.25f, 0.35f, 0.6f);
    return job;
}

struct Config {
    PixelPattern pattern;
    int spp;
    int depth;
    float threshold;
};

double rmse(const Image& a, const Image& b) {
    double sum = 0.0;
    auto clamp01 = [](float v) { return std::isfinite(v) ? std::clamp(static_cast<double>(v), 0.0, 1.0) : 0.0; };
    for (std::size_t i = 0; i < a.pixel_count(); ++i) {
        const RGB p = a.pixels()[i], q = b.pixels()[i];
        for (int c = 0; c < 3; ++c) {
            const double d = clamp01(p[c]) - clamp01(q[c]);
            sum += d * d;
        }
    }
    return std::sqrt(sum / (3.0 * static_cast<double>(a.pixel_count())));
}

}  // namespace

int main(int argc, char** argv) {
    std::string out_path, images;
    int runs = 3, width = 160;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--images") && i + 1 < argc)
            images = argv[++i];
        else if (!std::strcmp(argv[i], "--width") && i + 1 < argc)
            width = std::atoi(argv[++i]);
        else
            out_path = argv[i];
    }
    const int height = width * 3 / 4;
    std::ofstream file;
    if (!out_path.empty()) file.open(out_path);
    std::ostream& out = out_path.empty() ? std::cout : file;
    out << "scene,series,pattern,spp,max_depth,threshold,camera_rays_per_pixel,seconds_median,rmse,width,height,runs\n";

    const PinholeCamera checker_camera(CameraSpec{
        .eye = {0, 0, 0}, .look_at = {0, -0.35f, -1}, .vertical_fov_degrees = 50.0f, .width = width, .height = height});
    const FunctionRadiance checker([](const Ray& r, const SampleKey&, RayCounters&) { return checker_radiance(r); });
    const RenderJob whitted = whitted_job(width, height);

    std::vector<Config> configs{{PixelPattern::none, 1, 0, 0.0f}};
    for (PixelPattern p : {PixelPattern::grid, PixelPattern::random, PixelPattern::jittered})
        for (int spp : {4, 9, 16, 36, 64, 144}) configs.push_back({p, spp, 0, 0.0f});
    for (float threshold : {0.5f, 0.3f, 0.1f, 0.03f, 0.01f})
        configs.push_back({PixelPattern::adaptive, 1, 3, threshold});
    for (int depth : {2, 4}) configs.push_back({PixelPattern::adaptive, 1, depth, 0.1f});

    for (const std::string scene : {"checker", "whitted"}) {
        auto run = [&](const RenderSettings& s) {
            if (scene == "checker") return render(checker_camera, checker, s);
            RenderJob job = whitted;
            job.settings = s;
            return render_job(job);
        };
        RenderSettings ref_settings;
        ref_settings.pattern = PixelPattern::jittered;
        ref_settings.spp = 400;
        ref_settings.seed = 987654321;
        ref_settings.threads = 0;
        const Image reference = run(ref_settings).image;
        if (!images.empty()) {
            auto clamped = [](Image im) {
                auto f = [](float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f; };
                for (RGB& p : im.pixels()) p = RGB(f(p.r), f(p.g), f(p.b));
                return im;
            };
            write_png(clamped(reference), images + "/aa_" + scene + "_reference.png");
            write_png(clamped(run(RenderSettings{}).image), images + "/aa_" + scene + "_none.png");
        }
        for (const Config& c : configs) {
            RenderSettings s;
            s.pattern = c.pattern;
            s.spp = c.spp;
            s.adaptive.max_depth = c.depth;
            s.adaptive.threshold = c.threshold;
            s.threads = 1;
            std::vector<double> seconds;
            RenderResult result;
            for (int r = 0; r < runs; ++r) {
                const auto start = std::chrono::steady_clock::now();
                result = run(s);
                seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
            std::sort(seconds.begin(), seconds.end());
            double rays = 0.0;
            for (std::uint32_t n : result.samples) rays += n;
            rays /= static_cast<double>(result.samples.size());
            const std::string name = std::string(pixel_pattern_name(c.pattern));
            char series[64];
            if (c.pattern == PixelPattern::adaptive)
                std::snprintf(series, sizeof series, "adaptive depth %d", c.depth);
            else
                std::snprintf(series, sizeof series, "%s", name.c_str());
            out << scene << ',' << series << ',' << name << ',' << c.spp << ',' << c.depth << ',' << c.threshold << ','
                << rays << ',' << seconds[seconds.size() / 2] << ',' << rmse(result.image, reference) << ',' << width
                << ',' << height << ',' << runs << '\n';
            out.flush();
        }
    }
    return 0;
}
