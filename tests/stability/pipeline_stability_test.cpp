// The rest of the pipeline where such code is known to fail: refraction at the critical angle, noise far
// from the origin, tone mapping of black, NaN and extreme images, adaptive sampling on sources that never
// converge, and malformed meshes and images.
#include "record.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/geometry/mesh_io.hpp>
#include <rtlab/render/camera.hpp>
#include <rtlab/render/radiance_source.hpp>
#include <rtlab/render/renderer.hpp>
#include <rtlab/scene/plugin.hpp>
#include <rtlab/scene/scene_loader.hpp>
#include <rtlab/shading/optics.hpp>
#include <rtlab/textures/image_texture.hpp>
#include <rtlab/textures/perlin_noise.hpp>
#include <rtlab/textures/simplex_noise.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <catch2/catch.hpp>
#include <scratch_files.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace rtlab;
using rtlab::stability::record;

namespace {

struct CriticalAngle {
    std::int64_t tried = 0, disagree = 0, nonfinite = 0, out_of_range = 0;
    double worst_lost = 0.0, worst_snell = 0.0;
};

CriticalAngle critical_angle_sweep(float eta) {
    const double critical = std::asin(1.0 / eta);
    CriticalAngle c;
    auto& [tried, disagree, nonfinite, out_of_range, worst_lost, worst_snell] = c;
    {
        constexpr int n = 200000;
        for (int i = 0; i < n; ++i) {
            const double theta = critical + 1e-3 * (2.0 * i / (n - 1) - 1.0);
            const Vec3 d(static_cast<float>(std::sin(theta)), 0.0f, -static_cast<float>(std::cos(theta)));
            const Normal3 nrm(0.0f, 0.0f, 1.0f);
            const auto t = refract(d, nrm, eta);
            const float f = fresnel_dielectric(-d.z, eta);
            ++tried;
            if (!std::isfinite(f) || (t && !std::isfinite(glm::dot(*t, *t)))) ++nonfinite;
            if (!(f >= 0.0f && f <= 1.0f)) ++out_of_range;
            // refract() and the Fresnel term must agree on where total internal reflection starts: a ray
            // refract() reflects totally while F < 1 loses 1 - F of its energy (neither reflected nor sent on).
            if (!t && f < 1.0f) {
                ++disagree;
                worst_lost = std::max(worst_lost, 1.0 - f);
            }
            if (t) {
                // Snell: eta sin_i = sin_t, against the exact sine of the incident direction as a float.
                const double sin_i = std::hypot(double(d.x), double(d.y)) / glm::length(glm::dvec3(d));
                const glm::dvec3 td(*t);
                const double sin_t = std::hypot(td.x, td.y) / glm::length(td);
                worst_snell = std::max(worst_snell, std::abs(eta * sin_i - sin_t));
            }
        }
    }
    return c;
}

std::string critical_input(float eta) {
    char input[96];
    std::snprintf(input, sizeof input, "incidence within 1e-3 rad of the critical angle, eta %.2f", double(eta));
    return input;
}

}  // namespace

// Glass to air (eta = n_i / n_t = 1.5), and a weak interface (1.01), within 1e-3 rad of the critical angle.
TEST_CASE("refraction at the critical angle is finite and keeps Snell's law", "[stability]") {
    for (float eta : {1.5f, 1.01f}) {
        const CriticalAngle c = critical_angle_sweep(eta);
        record({"optics", "refract", critical_input(eta), c.tried, c.nonfinite + c.out_of_range,
                "non-finite direction or F outside [0, 1] (worst = Snell error)", c.worst_snell,
                "0, Snell error < 1e-3"});
        INFO("eta " << eta << ": Snell " << c.worst_snell);
        CHECK(c.tried > 0);
        CHECK(c.nonfinite == 0);
        CHECK(c.out_of_range == 0);
        CHECK(c.worst_snell < 1e-3);
    }
}

// Both decide total reflection from the one transmitted_cos2; they once used different formulas and
// disagreed within rounding of the critical angle (7 of 200,000 angles at eta 1.01).
TEST_CASE("refract and fresnel_dielectric agree on where total internal reflection starts", "[stability]") {
    for (float eta : {1.5f, 1.01f}) {
        const CriticalAngle c = critical_angle_sweep(eta);
        record({"optics", "refract + fresnel_dielectric", critical_input(eta), c.tried, c.disagree,
                "total reflection by refract() while F < 1 (worst = energy lost)", c.worst_lost, "0"});
        INFO("eta " << eta << ": " << c.disagree << " disagreements, worst loss " << c.worst_lost);
        CHECK(c.disagree == 0);
    }
}

TEST_CASE("noise stays bounded and smooth far from the origin", "[stability]") {
    const PerlinNoise perlin(7);
    const SimplexNoise simplex(7);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (double far : {1e3, 1e5, 1e6, 1e9}) {
        for (int which = 0; which < 2; ++which) {
            auto eval = [&](double x, double y, double z) {
                return which == 0 ? perlin.eval(x, y, z) : simplex.eval(x, y, z);
            };
            std::int64_t tried = 0, failures = 0;
            double worst_slope = 0.0, worst_period = 0.0;
            for (int i = 0; i < 20000; ++i) {
                const double x = far + 100.0 * u(rng), y = -far + 100.0 * u(rng), z = 0.5 * far + 100.0 * u(rng);
                const float a = eval(x, y, z);
                // A step of 1e-3 along x: noise with gradients of order 1 changes by about 1e-3; a lattice
                // lost to rounding shows up as jumps of order 1.
                const float b = eval(x + 1e-3, y, z);
                const double slope = std::abs(double(b) - double(a)) / 1e-3;
                worst_slope = std::max(worst_slope, slope);
                ++tried;
                if (!std::isfinite(a) || std::abs(a) > 1.0f || slope > 20.0) ++failures;
                if (which == 0) {  // Perlin's period is 256 in every axis: the same value a multiple of it away.
                    const double x0 = std::fmod(x, 256.0);
                    worst_period = std::max(worst_period, std::abs(double(eval(x0, y, z)) - double(a)));
                }
            }
            char input[64];
            std::snprintf(input, sizeof input, "3D points at coordinates ~%g", far);
            const char* name = which == 0 ? "Perlin noise" : "simplex noise";
            record({"textures", name, input, tried, failures,
                    "non-finite, |n| > 1 or slope > 20 (worst = largest slope)", worst_slope, "0"});
            if (which == 0)
                record({"textures", "Perlin noise period 256", input, tried, worst_period > 1e-4 ? 1 : 0,
                        "value differs from the same point moved back by whole periods (worst = difference)",
                        worst_period, "difference < 1e-4"});
            INFO(name << " at " << far << ": slope " << worst_slope << ", period " << worst_period);
            CHECK(failures == 0);
            CHECK(worst_period < 1e-4);
        }
    }
}

TEST_CASE("repeating textures wrap exactly far from the uv origin", "[stability]") {
    // A float uv at k + f keeps f only to the float spacing at k: that loss is the input's, reported as the
    // worst error (in texels). What the texture must do is wrap the value it was given exactly: the lookup
    // at k + f' equals the lookup at f' (f' the fraction the float kept), for whole periods k.
    auto image = std::make_shared<Image>(64, 64);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (RGB& p : image->pixels()) p = RGB(u(rng), u(rng), u(rng));
    const ImageTexture nearest(image, {WrapMode::repeat, ImageFilter::nearest});
    const ImageTexture bilinear(image, {WrapMode::repeat, ImageFilter::bilinear});
    const TextureRegistry registry = make_texture_registry();
    const auto checker = registry.create("checker", Params{});
    for (double k : {1e2, 1e4, 1e5, 1e6}) {
        for (int which = 0; which < 3; ++which) {
            const Texture& tex = which == 0   ? static_cast<const Texture&>(nearest)
                                 : which == 1 ? static_cast<const Texture&>(bilinear)
                                              : *checker;
            std::int64_t tried = 0, failures = 0;
            double worst_texels = 0.0;
            for (int i = 0; i < 20000; ++i) {
                const double fu = u(rng), fv = u(rng);
                const float kf = static_cast<float>(k);  // exact: k is a whole number below 2^24
                const Vec2 far(kf + static_cast<float>(fu), kf + static_cast<float>(fv));
                // Exact (Sterbenz): far and kf are within a factor 2 of each other.
                const Vec2 kept(far.x - kf, far.y - kf);
                TextureLookup a, b;
                a.uv = far;
                b.uv = kept;
                const RGB ca = tex.eval(a), cb = tex.eval(b);
                ++tried;
                // Bilinear weights are computed from the fraction, so allow float rounding there.
                const float tol = which == 1 ? 1e-3f : 0.0f;
                failures += std::abs(ca.r - cb.r) > tol || std::abs(ca.g - cb.g) > tol || std::abs(ca.b - cb.b) > tol;
                worst_texels = std::max(worst_texels, 64.0 * std::max(std::abs(kept.x - fu), std::abs(kept.y - fv)));
            }
            char input[64];
            std::snprintf(input, sizeof input, "uv at ~%g (whole periods away)", k);
            const char* name = which == 0   ? "image texture, nearest, repeat"
                               : which == 1 ? "image texture, bilinear, repeat"
                                            : "checker texture";
            record({"textures", name, input, tried, failures,
                    "lookup differs from the same fraction near the origin (worst = float uv loss, texels of 64)",
                    worst_texels, "0"});
            INFO(name << " at " << k);
            CHECK(failures == 0);
        }
    }
}

TEST_CASE("tone operators give finite values in 0 to 1 for black NaN and extreme images", "[stability]") {
    const ToneRegistry registry = make_tone_registry();
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    struct Case {
        const char* name;
        std::function<RGB(int, int)> pixel;
    };
    const std::vector<Case> cases = {
        {"all black", [](int, int) { return RGB(0.0f); }},
        {"all NaN", [&](int, int) { return RGB(nan); }},
        {"half NaN, half grey", [&](int x, int) { return x % 2 ? RGB(nan) : RGB(0.5f); }},
        {"one +inf pixel in grey", [&](int x, int y) { return x == 3 && y == 3 ? RGB(inf) : RGB(0.5f); }},
        {"one 1e30 pixel in grey", [](int x, int y) { return x == 3 && y == 3 ? RGB(1e30f) : RGB(0.5f); }},
        {"all 1e-30", [](int, int) { return RGB(1e-30f); }},
        {"all 1e30", [](int, int) { return RGB(1e30f); }},
        {"negative components", [](int x, int) { return RGB(-1.0f, 0.5f, x % 2 ? -1e30f : 2.0f); }},
    };
    for (const char* op_name : {"ward", "reinhard", "exposure", "aces"}) {
        const auto op = registry.create(op_name, Params{});
        for (const Case& c : cases) {
            Image hdr(16, 16);
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) hdr.at(x, y) = c.pixel(x, y);
            const Image out = op->apply(hdr);
            std::int64_t bad = 0;
            double worst = 0.0;
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) {
                    const RGB in = hdr.at(x, y), o = out.at(x, y);
                    const bool invalid_in = !std::isfinite(in.r) || !std::isfinite(in.g) || !std::isfinite(in.b);
                    bool wrong = false;
                    for (float v : {o.r, o.g, o.b}) {
                        if (!std::isfinite(v)) {
                            wrong = true;
                            worst = std::numeric_limits<double>::infinity();
                        } else if (v < 0.0f || v > 1.0f) {
                            wrong = true;
                            worst = std::max(worst, v < 0.0f ? -double(v) : double(v) - 1.0);
                        }
                        if (invalid_in && v != 0.0f) wrong = true;  // documented: invalid pixels come out black
                    }
                    bad += wrong;
                }
            record({"tone mapping", op_name, c.name, 256, bad,
                    "pixels non-finite, outside [0, 1], or not black for NaN/inf input (worst = distance outside)",
                    std::isfinite(worst) ? worst : 1e300, "0"});
            INFO(op_name << " on " << c.name);
            CHECK(bad == 0);
        }
    }
}

TEST_CASE("adaptive sampling terminates within its ray bound on sources that never converge", "[stability]") {
    const PinholeCamera camera(
        CameraSpec{.eye = {0, 0, 1}, .look_at = {0, 0, 0}, .vertical_fov_degrees = 40.0f, .width = 12, .height = 12});
    const float nan = std::numeric_limits<float>::quiet_NaN();
    struct Source {
        const char* name;
        FunctionRadiance::Function f;
    };
    const std::vector<Source> sources = {
        {"NaN everywhere", [nan](const Ray&, const SampleKey&, RayCounters&) { return RGB(nan); }},
        {"white noise (new value per sample)",
         [](const Ray& r, const SampleKey&, RayCounters&) {
             const auto h = std::hash<float>{}(r.direction.x * 7919.0f + r.direction.y * 104729.0f);
             return RGB((h & 1) ? 1.0f : 0.0f);
         }},
        {"checkerboard 1e-3 of a pixel (contrast 1e6)",
         [](const Ray& r, const SampleKey&, RayCounters&) {
             const double s = 2e5;
             const bool odd = (static_cast<long long>(std::floor(r.direction.x * s)) +
                               static_cast<long long>(std::floor(r.direction.y * s))) &
                              1;
             return RGB(odd ? 1e6f : 0.0f);
         }},
        {"constant", [](const Ray&, const SampleKey&, RayCounters&) { return RGB(0.5f); }},
    };
    for (const Source& s : sources) {
        const FunctionRadiance radiance(s.f);
        for (int depth : {0, 2, 4, 6}) {
            RenderSettings settings;
            settings.pattern = PixelPattern::adaptive;
            settings.adaptive.max_depth = depth;
            settings.adaptive.threshold = 0.0f;
            settings.threads = 1;
            const RenderResult result = render(camera, radiance, settings);
            const std::uint32_t bound = ((1u << depth) + 1u) * ((1u << depth) + 1u);
            std::int64_t over = 0;
            std::uint32_t most = 0;
            for (std::uint32_t n : result.samples) {
                over += n > bound || n == 0;
                most = std::max(most, n);
            }
            char method[64];
            std::snprintf(method, sizeof method, "adaptive, max depth %d, threshold 0", depth);
            record({"adaptive sampling", method, s.name, static_cast<std::int64_t>(result.samples.size()), over,
                    "pixels with no rays or more than (2^depth + 1)^2 (worst = most rays / bound)",
                    static_cast<double>(most) / bound, "0, worst <= 1"});
            INFO(s.name << " depth " << depth << ": most " << most << " of bound " << bound);
            CHECK(over == 0);
        }
    }
}

namespace {

enum class Outcome { rtlab_error, other_exception, loaded };

template <class Load>
Outcome try_load(Load&& load, std::string* message) {
    try {
        load();
        return Outcome::loaded;
    } catch (const Error& e) {
        *message = e.what();
        return Outcome::rtlab_error;
    } catch (const std::exception& e) {
        *message = e.what();
        return Outcome::other_exception;
    }
}

}  // namespace

// A Radiance HDR file cut after its header once loaded without error. A face with fewer than 3 corners is
// dropped (FORMATS.md), so a file whose only face has two corners holds no triangle: an error.
TEST_CASE("malformed meshes and images give an rtlab Error naming the file", "[stability]") {
    const auto dir = test::scratch_dir("stability_malformed");
    struct File {
        const char* name;
        std::string bytes;
    };
    const std::string ply_head =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const std::string ply_bin =
        "ply\nformat binary_little_endian 1.0\nelement vertex 300\nproperty float x\nproperty float y\n"
        "property float z\nelement face 100\nproperty list uchar int vertex_indices\nend_header\n";
    const std::vector<File> meshes = {
        {"empty.obj", ""},
        {"index_out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"},
        {"index_zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"},
        {"nan_vertex.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"},
        {"text_in_vertex.obj", "v 0 zero 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
        {"face_with_two_corners.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"},
        {"no_header.ply", "element vertex 3\n0 0 0\n"},
        {"truncated_ascii.ply", ply_head + "0 0 0\n1 0 0\n"},
        {"index_out_of_range.ply", ply_head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"},
        {"negative_count.ply", "ply\nformat ascii 1.0\nelement vertex -3\nproperty float x\nend_header\n"},
        {"truncated_binary.ply", ply_bin + std::string(100, '\0')},
        {"huge_count.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n" +
             std::string(64, '\0')},
        {"garbage.ply", std::string("ply\n\xff\xfe\x00\x01garbage", 16)},
    };
    const std::vector<File> images = {
        {"empty.png", ""},
        {"truncated.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x10", 20)},
        {"garbage.png", "this is not an image"},
        {"header_only.pfm", "PF\n16 16\n-1.0\n"},
        {"negative_size.pfm", "PF\n-16 16\n-1.0\n"},
        {"huge_size.pfm", "PF\n100000 100000\n-1.0\n" + std::string(64, '\0')},
        {"truncated.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16 +X 16\n"},
    };
    for (int kind = 0; kind < 2; ++kind) {
        std::int64_t tried = 0, failures = 0;
        std::string failed;
        for (const File& f : kind == 0 ? meshes : images) {
            const auto path = dir / f.name;
            std::ofstream(path, std::ios::binary) << f.bytes;
            std::string message;
            const Outcome o = kind == 0 ? try_load([&] { (void)load_mesh(path); }, &message)
                                        : try_load([&] { (void)read_image(path); }, &message);
            ++tried;
            const bool named = message.find(f.name) != std::string::npos;
            const bool ok = o == Outcome::rtlab_error && named;
            failures += !ok;
            if (!ok) failed += std::string(failed.empty() ? ": " : ", ") + f.name;
            INFO(f.name << ": " << (o == Outcome::loaded ? "loaded" : message));
            CHECK(ok);
        }
        record({"loaders", kind == 0 ? "load_mesh (OBJ, PLY)" : "read_image (PNG, PFM, HDR)",
                kind == 0 ? "malformed meshes: empty, bad indices, NaN/text vertices, truncated, lying headers"
                          : "malformed images: empty, truncated, garbage, bad sizes",
                tried, failures, "loaded silently, or failed without an rtlab::Error naming the file", std::nan(""),
                "0"});
    }
    std::filesystem::remove_all(dir);
}

// Every malformed scene file of tests/scene/bad_scenes given to the loader itself (the app's runner,
// run_bad_scenes.cmake, checks rtlab-render's exit status and output on the same files): each must be one
// rtlab::Error holding every line its expected.txt names. Cases that need command-line flags (args.txt) are
// the app's alone.
TEST_CASE("malformed scene files give an rtlab Error with every expected message", "[stability]") {
    const std::filesystem::path cases = std::filesystem::path(RTLAB_SOURCE_DIR) / "tests/scene/bad_scenes";
    std::int64_t tried = 0, failures = 0;
    for (const auto& entry : std::filesystem::directory_iterator(cases)) {
        if (!entry.is_directory() || std::filesystem::exists(entry.path() / "args.txt")) continue;
        std::vector<std::string> expected;
        std::ifstream in(entry.path() / "expected.txt");
        for (std::string line; std::getline(in, line);)
            if (!line.empty()) expected.push_back(line);
        SceneRegistries registries = SceneRegistries::builtins();
        PluginHost plugins(registries.materials, registries.textures, registries.lights, SearchPath());
        SceneLoadOptions options;
        options.use_environment = false;
        options.registries = &registries;
        options.plugin_loader = [&](const std::string& name) { plugins.load_by_name(name, "scene.json: plugins"); };
        std::string message;
        bool rtlab_error = false;
        try {
            (void)load_scene(entry.path() / "scene.json", options);
        } catch (const Error& e) {
            rtlab_error = true;
            message = e.what();
        } catch (const std::exception& e) {
            message = std::string("not an rtlab::Error: ") + e.what();
        }
        const bool all_named = std::all_of(expected.begin(), expected.end(), [&](const std::string& line) {
            return message.find(line) != std::string::npos;
        });
        const bool ok = rtlab_error && !expected.empty() && all_named;
        ++tried;
        failures += !ok;
        INFO(entry.path().filename().string() << ": " << (message.empty() ? "loaded" : message));
        CHECK(ok);
    }
    CHECK(tried >= 20);
    record({"loaders", "load_scene (JSON)",
            "malformed scene files: syntax, types, unknown and duplicate keys, dangling names, bad meshes, sizes, "
            "plugin paths (tests/scene/bad_scenes)",
            tried, failures, "loaded, or failed without an rtlab::Error holding the expected messages", std::nan(""),
            "0"});
}
