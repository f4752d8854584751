// Environment maps through render: EXR input (DWAB-compressed files read through OpenEXR, bad files named), the
// studio maps of blender-data found by logical name and sampled by their pdf, and the direct and path estimators
// of the light a diffuse surface reflects under a map against a deterministic quadrature of the same integral
// (a uniformly sampled reference would be useless beside a texel of 33,952), and a map turned by `rotation`
// lighting the side of a sphere it should in a render.
#include "../shading/environment_checks.hpp"
#include "scene_fixtures.hpp"

#include <rtlab/core/data_path.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/core/frame.hpp>
#include <rtlab/render/exr.hpp>
#include <rtlab/render/image_input.hpp>
#include <rtlab/render/render_job.hpp>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <catch2/catch.hpp>
#include <scratch_files.hpp>
#include <skip.hpp>

#include <cmath>
#include <fstream>

using namespace rtlab;
using namespace rtlab::test;
using Catch::Contains;
namespace fs = std::filesystem;

namespace {

const char* const kStudioMaps[] = {"city", "courtyard", "forest", "interior", "night", "studio", "sunrise", "sunset"};

// The package file of a logical name, by the manifest alone (not ../shared or the environment).
std::optional<fs::path> package_file(const std::string& name) {
    const DataPath packages;
    if (auto f = packages.find(name)) return f->path;
    return std::nullopt;
}

// A smooth half-float image written with DWAB compression, as Blender's studio maps are.
Image write_dwab(const fs::path& file, int w, int h) {
    Image expected(w, h);
    std::vector<half> r(w * h), g(w * h), b(w * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const RGB c(0.5f + 0.4f * std::sin(0.1f * x), 2.0f + 0.05f * y, 100.0f * (1.0f + float(x + y) / (w + h)));
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            r[i] = half(c.r), g[i] = half(c.g), b[i] = half(c.b);
            expected.at(x, y) = RGB(float(r[i]), float(g[i]), float(b[i]));
        }
    Imf::Header header(w, h);
    header.compression() = Imf::DWAB_COMPRESSION;
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::HALF));
    Imf::OutputFile out(file.c_str(), header);
    Imf::FrameBuffer fb;
    const std::size_t xs = sizeof(half), ys = sizeof(half) * w;
    fb.insert("R", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(r.data()), xs, ys));
    fb.insert("G", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(g.data()), xs, ys));
    fb.insert("B", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(b.data()), xs, ys));
    out.setFrameBuffer(fb);
    out.writePixels(h);
    return expected;
}

struct PixelStats {
    double mean = 0.0, standard_error = 0.0;
};

// Green channel of the pixels: their mean and its standard error (every pixel an independent estimate).
PixelStats pixel_stats(const Image& image) {
    double sum = 0.0, sum2 = 0.0;
    const auto n = static_cast<double>(image.pixel_count());
    for (const RGB& c : image.pixels()) {
        sum += c.g;
        sum2 += double(c.g) * c.g;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1.0))};
}

// A Lambert patch of albedo `albedo` facing n, filling the view of a camera on n looking back at it, under the
// map alone: every pixel sees the light the patch reflects (the patch cannot see itself).
RenderJob patch_under(std::shared_ptr<const EnvironmentMap> map, const Vec3& n, float albedo, IntegratorKind kind,
                      int size, int spp) {
    const Frame f = Frame::from_normal(n);
    RenderJob job;
    CameraSpec camera{.eye = Point3(2.0f * n), .look_at = Point3(0.0f), .up = f.s};
    camera.vertical_fov_degrees = 10.0f;
    camera.width = camera.height = size;
    job.camera = std::make_shared<PinholeCamera>(camera);
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
        {std::make_shared<Quad>(Point3(-f.s - f.t), 2.0f * f.s, 2.0f * f.t), lambert(RGB(albedo)), {}, "patch"}});
    job.environment = std::move(map);
    job.integrator = kind;
    job.path.max_depth = 4;
    job.settings.pattern = PixelPattern::sobol;
    job.settings.spp = spp;
    job.settings.seed = 5;
    return job;
}

// Both estimators against the quadrature, within 3 standard errors, and informative (error below 2%).
void check_reflected(std::shared_ptr<const EnvironmentMap> map, const Vec3& n, const char* name) {
    const float albedo = 0.8f;
    const double expected = albedo * reflected_by_quadrature(*map, glm::dvec3(glm::normalize(n)));
    for (IntegratorKind kind : {IntegratorKind::direct, IntegratorKind::path}) {
        const PixelStats s = pixel_stats(render_job(patch_under(map, glm::normalize(n), albedo, kind, 16, 64)).image);
        INFO(name << ", " << integrator_name(kind) << ": " << s.mean << " +- " << s.standard_error << ", quadrature "
                  << expected);
        CHECK(std::abs(s.mean - expected) <= 3.0 * s.standard_error);
        CHECK(s.standard_error < 0.02 * expected);
    }
}

}  // namespace

TEST_CASE("DWAB-compressed EXR files read through OpenEXR", "[environment]") {
    const fs::path dir = fresh_dir("rtlab_env_", "dwab");
    const Image expected = write_dwab(dir / "dwab.exr", 64, 32);
    // Under any name: the magic number decides.
    fs::copy_file(dir / "dwab.exr", dir / "dwab.hdr");
    for (const char* name : {"dwab.exr", "dwab.hdr"}) {
        const Image back = read_image_file(dir / name);
        REQUIRE(back.width() == 64);
        REQUIRE(back.height() == 32);
        // DWAB is lossy for half channels: within a few percent on a smooth image.
        double worst = 0.0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 64; ++x)
                for (int c = 0; c < 3; ++c) {
                    const float e = (&expected.at(x, y).r)[c], b = (&back.at(x, y).r)[c];
                    worst = std::max(worst, double(std::abs(b - e) / e));
                }
        INFO(name << ": worst relative error " << worst);
        CHECK(worst < 0.03);
    }
}

TEST_CASE("bad EXR files are errors naming the file and the problem", "[environment]") {
    const fs::path dir = fresh_dir("rtlab_env_", "bad");
    CHECK_THROWS_WITH(read_image_file(dir / "none.exr"), Contains("none.exr"));
    write_exr(Image(16, 8, RGB(1.0f)), dir / "whole.exr");
    const std::vector<unsigned char> bytes = read_binary_file(dir / "whole.exr");
    write_binary_file(dir / "cut.exr", std::span(bytes).first(bytes.size() / 2));
    CHECK_THROWS_WITH(read_image_file(dir / "cut.exr"), Contains("cut.exr") && Contains("cannot read EXR"));
    const unsigned char magic_only[] = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0, 'x', 'y'};
    write_binary_file(dir / "junk.exr", magic_only);
    CHECK_THROWS_WITH(read_image_file(dir / "junk.exr"), Contains("junk.exr") && Contains("cannot read EXR"));
    // core, which does not link OpenEXR, says who reads it.
    CHECK_THROWS_WITH(read_image(dir / "whole.exr"), Contains("whole.exr") && Contains("rtlab::render"));
    CHECK(read_image_file(dir / "whole.exr").at(3, 3) == RGB(1.0f));
}

TEST_CASE("the studio maps of blender-data are found by logical name and hold true HDR", "[environment]") {
    int found = 0;
    for (const char* name : kStudioMaps) {
        const std::string logical = std::string("envmaps/") + name + ".exr";
        const auto file = package_file(logical);
        if (!file) continue;
        ++found;
        INFO(logical);
        CHECK(is_exr_file(*file));
        const Image image = read_image_file(*file);
        CHECK(image.width() == 1024);
        CHECK(image.height() == 512);
        float peak = 0.0f;
        for (const RGB& c : image.pixels()) {
            REQUIRE(std::isfinite(c.r + c.g + c.b));
            peak = std::max(peak, c.max_component());
        }
        CHECK(peak > 50.0f);  // peaks from 55 to 33,952: light a display cannot show
    }
    if (found == 0) return test::skip("blender-data is not installed (scripts/setup.sh installs it)");
    CHECK(found == 8);
}

TEST_CASE("environment maps sample by luminance: a synthetic spot and a studio map", "[environment]") {
    // The spot map: a sky of 0.1 to 1 with a 3 x 3 sun of 30,000 near the horizon, and black ground.
    Image spot(256, 128);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 256; ++x) spot.at(x, y) = y < 64 ? RGB(0.1f + 0.9f * y / 64.0f, 0.5f, 1.0f) : RGB(0.0f);
    for (int y = 50; y < 53; ++y)
        for (int x = 200; x < 203; ++x) spot.at(x, y) = RGB(30000.0f);
    std::vector<std::pair<std::string, std::shared_ptr<EnvironmentMap>>> maps{
        {"spot", std::make_shared<EnvironmentMap>(spot, EnvironmentMapOptions{.rotation_degrees = 30.0f})}};
    // city.exr: a sun of 33,952 over a sky of about 1.
    if (auto file = package_file("envmaps/city.exr"))
        maps.emplace_back("city", std::make_shared<EnvironmentMap>(read_image_file(*file),
                                                                   EnvironmentMapOptions{.rotation_degrees = -120.0f}));
    const double level = sidak_level(1e-3, 2);
    std::uint64_t seed = 1;
    for (const auto& [name, map] : maps) {
        Rng rng(seed++);
        const int n = 200000 / kSampleScale;
        const int group = map->distribution().columns() / 64;  // 64 x 32 bins
        const EnvironmentSamplingResult r = check_environment_sampling(*map, rng, n, group, group);
        INFO(name << ": chi2 " << r.chi2.statistic << " dof " << r.chi2.dof << " p " << r.chi2.p_value << " ("
                  << r.chi2.failure << r.chi2.worst << "), pdf integral " << r.pdf_integral << ", mismatches "
                  << r.pdf_mismatches);
        CHECK(r.chi2.failure.empty());
        CHECK(r.chi2.p_value > level);
        CHECK(r.pdf_integral == Approx(1.0).epsilon(1e-3));
        CHECK(r.pdf_mismatches <= n / 1000);
    }
    if (maps.size() == 1) return test::skip("blender-data is not installed: the studio maps were not tested");
}

TEST_CASE("direct and path under a map match a per-texel quadrature of the reflected light", "[environment]") {
    // A synthetic map with a small bright spot, and (when installed) the studio map with the 33,952 peak.
    Image spot(128, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 128; ++x) spot.at(x, y) = RGB(0.2f + 0.01f * y, 0.3f + 0.2f * std::sin(0.05f * x), 0.4f);
    spot.at(90, 20) = RGB(20000.0f);
    check_reflected(std::make_shared<EnvironmentMap>(spot, EnvironmentMapOptions{.rotation_degrees = 50.0f}),
                    Vec3(0.3f, 0.8f, -0.5f), "spot");
    check_reflected(std::make_shared<EnvironmentMap>(spot), Vec3(-0.2f, -0.3f, 0.9f), "spot, tilted down");
    const auto file = package_file("envmaps/city.exr");
    if (!file) return test::skip("blender-data is not installed: the studio map was not tested");
    const auto city = std::make_shared<EnvironmentMap>(read_image_file(*file));
    check_reflected(city, Vec3(0.2f, 1.0f, 0.1f), "city, facing up");
    check_reflected(city, Vec3(-0.6f, 0.3f, 0.7f), "city, a wall");
}
