// Photon mapping against the path tracer on the Cornell box (scenes/cornell_box.json, 32 x 32): sppm approaches the
// converged path-traced image as it iterates, and photon and sppm agree with it with a glass block too, whose caustic
// would show light counted twice. The references are the path tracer's at 16384 samples per pixel (8x8 blocks of
// 64 pixels: about 0.1% noise per block), in tests/scene/reference/; RTLAB_UPDATE_REFERENCES=1 renders them again
// (about a minute each on 2 cores). Differences are between 8x8 block means of the pixels' channel means, relative.
#include <rtlab/core/image.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/render/sampled_lights.hpp>
#include <rtlab/render/sppm.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <catch2/catch.hpp>
#include <shared_data.hpp>
#include <skip.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = RTLAB_SOURCE_DIR;
constexpr int kSize = 32, kBlock = 8;

// The Cornell box at 32 x 32; with `glass`, its short block in smooth glass.
RenderJob cornell_box(bool glass) {
    SceneLoadOptions options;
    options.use_environment = false;
    options.overrides.width = options.overrides.height = kSize;
    RenderJob job = load_scene(kSource / "scenes/cornell_box.json", options).job;
    if (glass) {
        static const MaterialRegistry materials = make_material_registry();
        std::vector<SceneObject> objects = job.scene->objects();
        bool found = false;
        for (SceneObject& o : objects)
            if (o.name == "short_block") {
                o.material = materials.create("glass", Params());
                found = true;
            }
        REQUIRE(found);
        job.scene = std::make_shared<const Scene>(std::move(objects));
    }
    job.settings.threads = 2;
    return job;
}

Image reference(const std::string& name, const RenderJob& scene) {
    const fs::path file = kSource / "tests/scene/reference" / (name + ".pfm");
    if (std::getenv("RTLAB_UPDATE_REFERENCES")) {
        RenderJob job = scene;
        job.integrator = IntegratorKind::path;
        job.settings.pattern = PixelPattern::sobol;
        job.settings.spp = 16384;
        job.settings.seed = 1000;
        job.settings.threads = 0;
        write_image(render_job(job).image, file);
        WARN("wrote " + file.string());
    }
    return read_image(file, ColorEncoding::linear);
}

// Mean and largest over the 8x8 blocks of |image - reference| / reference, of each block's mean over pixels and
// channels.
struct Difference {
    double mean = 0.0, largest = 0.0;
};
Difference block_differences(const Image& image, const Image& reference) {
    REQUIRE(image.width() == reference.width());
    REQUIRE(image.height() == reference.height());
    Difference d;
    int blocks = 0;
    for (int by = 0; by + kBlock <= image.height(); by += kBlock)
        for (int bx = 0; bx + kBlock <= image.width(); bx += kBlock) {
            double a = 0.0, r = 0.0;
            for (int y = by; y < by + kBlock; ++y)
                for (int x = bx; x < bx + kBlock; ++x) {
                    a += channel_mean(image.at(x, y));
                    r += channel_mean(reference.at(x, y));
                }
            d.mean += std::abs(a - r) / r;
            d.largest = std::max(d.largest, std::abs(a - r) / r);
            ++blocks;
        }
    d.mean /= blocks;
    return d;
}

double block_difference(const Image& image, const Image& reference) { return block_differences(image, reference).mean; }

// sppm's image after each count of iterations in `stops` (increasing).
std::vector<Image> sppm_images(const RenderJob& job, std::vector<int> stops) {
    const SampledLights s = make_sampled_lights(job.scene, job.lights, job.whitted);
    ProgressiveSettings settings;
    settings.seed = 1;
    settings.threads = job.settings.threads;
    SppmRenderer sppm(*job.camera, *s.scene, s.lights, s.sphere, job.path, job.photons, settings);
    std::vector<Image> out;
    for (const int n : stops) {
        while (sppm.iterations() < n) REQUIRE(sppm.iterate());
        out.push_back(sppm.image());
    }
    return out;
}

}  // namespace

TEST_CASE("sppm approaches the path tracer's converged Cornell box as it iterates", "[photon_scene]") {
    // Measured (scripts/charts.sh --photon, docs/data/sppm_convergence.csv): the mean relative block difference falls
    // from 7.3% after one iteration of 20000 photons to 0.24% after 1024. Here 32 iterations of 10000 photons (about
    // a second): 2.3% after 4, 1.0% after 32; the difference must fall by a third and end below 2.5%.
    RenderJob job = cornell_box(false);
    const Image ref = reference("cornell_box.path", job);
    job.photons.photons = 10000;
    const std::vector<Image> images = sppm_images(job, {4, 32});
    const double early = block_difference(images[0], ref), late = block_difference(images[1], ref);
    INFO("mean relative block difference: " << early << " after 4 iterations, " << late << " after 32");
    CHECK(late < 0.025);
    CHECK(late < 0.67 * early);
    // The comparison can fail: the direct light alone (max_depth 1) is far from it.
    job.path.max_depth = 1;
    CHECK(block_difference(sppm_images(job, {4})[0], ref) > 0.2);
}

TEST_CASE("photon and sppm count no light twice: a glass block's caustic in the Cornell box", "[photon_scene]") {
    // Light reaches the floor and walls straight (next-event estimation), through the glass (the caustic map or
    // photons), and after diffuse bounces (the global map, final gather, or photons): an image that counted a part
    // twice, or missed one, would be off by that part in the blocks it lights.
    RenderJob job = cornell_box(true);
    const Image ref = reference("cornell_box_glass.path", job);
    job.photons.photons = 20000;
    const Difference sppm = block_differences(sppm_images(job, {24})[0], ref);
    job.integrator = IntegratorKind::photon;
    job.photons.photons = 100000;
    job.settings.pattern = PixelPattern::sobol;
    job.settings.spp = 8;
    job.photons.gather = 0;
    const Difference photon_global = block_differences(render_job(job).image, ref);
    job.photons.gather = 1;
    const Difference photon_gather = block_differences(render_job(job).image, ref);
    INFO("relative block differences, mean and largest: sppm "
         << sppm.mean << " " << sppm.largest << ", photon without final gather " << photon_global.mean << " "
         << photon_global.largest << ", with " << photon_gather.mean << " " << photon_gather.largest);
    // Measured: sppm 0.9%, photon 1.9% and 2.1% (largest blocks 2% for sppm, 8% for photon: the corners' blur); with
    // the caustic photons in the global map too (the caustic counted twice) photon without final gather is 3.9%.
    CHECK(sppm.mean < 0.02);
    CHECK(photon_global.mean < 0.03);
    CHECK(photon_gather.mean < 0.03);
}

namespace {

// scenes/caustics.json at 64 x 48: the glass sphere's caustic (what sppm adds to `direct` on the floor under the
// sphere, in its shadow) is the brightest thing of the floor, far brighter than the floor in the lamp's direct light,
// and in the sphere's shadow, below the sphere's image.
void check_caustics(test::DataSource source) {
    const auto data = test::pinned_data_path(source);
    if (!data) return test::skip(std::string("scenes/caustics.json: no ") + test::source_name(source) + " data");
    SceneLoadOptions options;
    options.use_environment = false;
    options.data_path = *data;
    options.overrides.width = 64;
    options.overrides.height = 48;
    RenderJob job = load_scene(kSource / "scenes/caustics.json", options).job;
    job.settings.threads = 2;
    job.settings.spp = 8;
    job.photons.photons = 50000;
    REQUIRE(job.integrator == IntegratorKind::sppm);
    const Image sppm = render_job(job).image;
    job.integrator = IntegratorKind::direct;
    job.settings.spp = 16;
    const Image direct = render_job(job).image;
    // The floor in direct light: the 90th percentile of the lower half's direct values (the floor nearest the lamp).
    std::vector<float> floor;
    int peak_x = 0, peak_y = 0;
    float peak = 0.0f;
    for (int y = 24; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            floor.push_back(channel_mean(direct.at(x, y)));
            const float added = channel_mean(sppm.at(x, y)) - channel_mean(direct.at(x, y));
            if (added > peak) peak = added, peak_x = x, peak_y = y;
        }
    std::sort(floor.begin(), floor.end());
    const float lit = floor[floor.size() * 9 / 10];
    INFO(test::source_name(source) << ": caustic " << peak << " at (" << peak_x << ", " << peak_y << "), the lit floor "
                                   << lit << ", direct light there " << channel_mean(direct.at(peak_x, peak_y)));
    CHECK(peak > 10.0f * lit);                                    // measured: 80 times
    CHECK(channel_mean(direct.at(peak_x, peak_y)) < 0.2f * lit);  // in the shadow
    CHECK(peak_x >= 10);
    CHECK(peak_x <= 24);  // under the sphere's image (the sphere is left of the middle)
}

}  // namespace

TEST_CASE("scenes/caustics.json: the sphere's caustic under it with the package data", "[photon_scene]") {
    check_caustics(test::DataSource::packages);
}
TEST_CASE("scenes/caustics.json: the sphere's caustic under it with the shared data", "[photon_scene]") {
    check_caustics(test::DataSource::shared);
}
