// Plugin modules: the toon and wood examples loaded, created by name and rendered; modules with wrong
// records, taken names and bad names refused with messages that say what is wrong.
#include <rtlab/core/error.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/scene/plugin.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <catch2/catch.hpp>

#include "declaration_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <set>
#include <tuple>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

const fs::path kExampleDir = RTLAB_TEST_EXAMPLE_DIR;
const fs::path kModuleDir = RTLAB_TEST_MODULE_DIR;

fs::path module(const std::string& name) { return fs::canonical(kModuleDir / (name + ".so")); }
fs::path example(const std::string& name) { return fs::canonical(kExampleDir / (name + ".so")); }

/// A host over fresh registries holding the built-ins, as a program would have them.
struct Host {
    MaterialRegistry materials = make_material_registry();
    TextureRegistry textures = make_texture_registry();
    LightRegistry lights = make_light_registry();
    PluginHost plugins;
    explicit Host(SearchPath path = SearchPath({kExampleDir}))
        : plugins(materials, textures, lights, std::move(path)) {}
};

std::string text(const std::exception& e) { return e.what(); }

/// The message of the rtlab::Error that f throws ("" and a failed check when it throws none).
template <class F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return text(e);
    }
    FAIL_CHECK("no rtlab::Error was thrown");
    return {};
}

std::shared_ptr<const Light> light(Host& h, const std::string& name, Params p) { return h.lights.create(name, p); }

Params::List list(float a, float b, float c) { return {a, b, c}; }

/// A 64 x 64 view of a unit sphere at the origin, lit in the classic convention (no fall-off, so toon
/// bands are flat) by a point light at (5, 5, 5), over a blue background.
Image render_sphere(Host& h, std::shared_ptr<const Material> material) {
    RenderJob job;
    job.scene = std::make_shared<Scene>(
        std::vector<SceneObject>{{std::make_shared<Sphere>(Point3(0.0f), 1.0f), std::move(material), {}, "ball"}});
    job.camera = std::make_shared<PinholeCamera>(
        CameraSpec{.eye = {0, 0, 5}, .look_at = {0, 0, 0}, .vertical_fov_degrees = 30.0f, .width = 64, .height = 64});
    Params p;
    p.set("position", list(5, 5, 5)).set("intensity", 1.0);
    job.lights = {light(h, "point", p)};
    job.whitted.convention = Convention::classic;
    job.whitted.background = RGB(0.1f, 0.2f, 0.9f);
    job.settings.threads = 2;
    return render_job(job).image;
}

/// A 96 x 96 view straight down onto the square [-2.2, 2.2]^2 of the plane y = 0, lit straight down by a
/// directional light of intensity 1: in the classic convention a Lambert pixel is its albedo exactly.
struct FloorView {
    std::shared_ptr<PinholeCamera> camera = std::make_shared<PinholeCamera>(CameraSpec{.eye = {0, 6, 0},
                                                                                       .look_at = {0, 0, 0},
                                                                                       .up = {0, 0, -1},
                                                                                       .vertical_fov_degrees = 40.0f,
                                                                                       .width = 96,
                                                                                       .height = 96});

    Image render(Host& h, std::shared_ptr<const Material> material) const {
        RenderJob job;
        job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
            {std::make_shared<Quad>(Point3(-2.2f, 0.0f, 2.2f), Vec3(4.4f, 0, 0), Vec3(0, 0, -4.4f)),
             std::move(material),
             {},
             "floor"}});
        job.camera = camera;
        Params p;
        p.set("direction", list(0, -1, 0)).set("intensity", 1.0);
        job.lights = {light(h, "directional", p)};
        job.whitted.convention = Convention::classic;
        job.settings.threads = 2;
        return render_job(job).image;
    }

    /// Where pixel (x, y)'s centre ray meets the plane y = 0.
    Point3 hit(int x, int y) const {
        const Ray ray = camera->ray(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        return ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
    }
};

float luminance(const RGB& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

std::shared_ptr<const Texture> wood(Host& h, float rings, float turbulence) {
    Params p;
    p.set("rings", static_cast<double>(rings)).set("turbulence", static_cast<double>(turbulence));
    return h.textures.create("wood", p);
}

std::shared_ptr<const Material> lambert_with(Host& h, std::shared_ptr<const Texture> albedo) {
    Params p;
    p.set_object<Texture>("albedo", std::const_pointer_cast<Texture>(std::move(albedo)));
    return h.materials.create("lambert", p);
}

/// Rising jumps of more than half the light-to-dark difference along row y, moving away from the centre:
/// the outer edges of growth rings, where late (dark) wood meets the next ring's early (light) wood.
int ring_edges(const Image& image, int y) {
    const float step = 0.5f * (luminance(RGB(0.78f, 0.56f, 0.33f)) - luminance(RGB(0.42f, 0.24f, 0.11f)));
    int edges = 0;
    const int centre = image.width() / 2;
    for (int x = centre; x + 1 < image.width(); ++x)
        edges += luminance(image.at(x + 1, y)) - luminance(image.at(x, y)) > step;
    for (int x = centre - 1; x > 0; --x) edges += luminance(image.at(x - 1, y)) - luminance(image.at(x, y)) > step;
    return edges;
}

}  // namespace

TEST_CASE("the toon and wood examples load by name and register their types", "[plugins]") {
    Host h;
    const LoadedPlugin toon = h.plugins.load_by_name("toon");
    const LoadedPlugin wood = h.plugins.load_by_name("wood.so");
    CHECK(toon.file == example("toon"));
    CHECK(toon.materials == std::vector<std::string>{"toon"});
    CHECK(toon.textures.empty());
    CHECK(wood.textures == std::vector<std::string>{"wood"});
    CHECK(toon.description == "toon: a cel-shading material");
    CHECK(h.materials.contains("toon"));
    CHECK(h.textures.contains("wood"));
    CHECK(h.materials.spec("toon").find("levels") != nullptr);
    CHECK(h.materials.spec("toon").find("opacity") != nullptr);  // the shared keys, extended with
    CHECK(h.textures.spec("wood").find("axis")->words == std::vector<std::string>{"x", "y", "z"});
    REQUIRE(h.plugins.loaded().size() == 2);
    // Loading a module again, by path or by name, is a no-op (a scene may name what --plugin loaded).
    CHECK(h.plugins.load_file(kExampleDir / "toon.so").file == toon.file);
    CHECK(h.plugins.load_by_name("toon").file == toon.file);
    CHECK(h.plugins.loaded().size() == 2);
}

TEST_CASE("the example plugins' types read exactly the keys they declare", "[plugins]") {
    Host h;
    h.plugins.load_by_name("toon");
    h.plugins.load_by_name("wood");
    test::Samples samples;
    test::check_type(h.materials, "toon", samples);
    test::check_type(h.textures, "wood", samples);
}

TEST_CASE("a toon sphere renders in flat bands and a Lambert one does not", "[plugins]") {
    Host h;
    h.plugins.load_file(example("toon"));
    const RGB colour(0.8f, 0.4f, 0.2f), highlight(0.5f);
    for (int levels : {3, 5}) {
        Params p;
        p.set("color", list(colour.r, colour.g, colour.b))
            .set("levels", static_cast<double>(levels))
            .set("highlight", list(highlight.r, highlight.g, highlight.b));
        const Image toon = render_sphere(h, h.materials.create("toon", p));
        if (levels == 3) write_png(toon, "plugin_toon_sphere.png");
        // Every pixel of the sphere is one of: unlit (0), a band colour * k / levels, or a band plus the
        // highlight (whose disc may straddle the edge of the top band); each unlit or band shade is seen, and
        // the highlight is seen.
        std::vector<RGB> allowed{RGB(0.0f)};
        for (int k = 1; k <= levels; ++k)
            allowed.push_back(colour * (static_cast<float>(k) / static_cast<float>(levels)));
        for (int k = 1; k <= levels; ++k) allowed.push_back(allowed[static_cast<std::size_t>(k)] + highlight);
        std::vector<int> seen(allowed.size(), 0);
        int sphere = 0, other = 0;
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                const RGB c = toon.at(x, y);
                if (c == RGB(0.1f, 0.2f, 0.9f)) continue;
                ++sphere;
                bool found = false;
                for (std::size_t i = 0; i < allowed.size() && !found; ++i) {
                    if (std::abs(c.r - allowed[i].r) < 1e-6f && std::abs(c.g - allowed[i].g) < 1e-6f &&
                        std::abs(c.b - allowed[i].b) < 1e-6f) {
                        ++seen[i];
                        found = true;
                    }
                }
                other += !found;
            }
        }
        INFO("levels " << levels << ", sphere pixels " << sphere);
        CHECK(sphere > 900);
        CHECK(other == 0);
        for (int i = 0; i <= levels; ++i) {
            INFO("shade " << i);
            CHECK(seen[static_cast<std::size_t>(i)] > 0);
        }
        const auto lit = static_cast<std::ptrdiff_t>(levels) + 1;
        const int highlighted = std::accumulate(seen.begin() + lit, seen.end(), 0);
        const auto shades = std::count_if(seen.begin(), seen.end(), [](int n) { return n > 0; });
        CHECK(highlighted > 0);
        CHECK(highlighted < sphere / 20);
        CHECK(shades <= levels + 3);
        WARN("toon levels " << levels << ": " << shades << " distinct shades over " << sphere << " pixels, "
                            << highlighted << " highlighted");
    }

    Params p;
    p.set("albedo", list(colour.r, colour.g, colour.b));
    const Image lambert = render_sphere(h, h.materials.create("lambert", p));
    std::set<std::tuple<float, float, float>> shades;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) shades.insert({lambert.at(x, y).r, lambert.at(x, y).g, lambert.at(x, y).b});
    CHECK(shades.size() > 300);
    WARN("lambert: " << shades.size() << " distinct shades");
}

TEST_CASE("a wood floor shows the growth rings the texture computes", "[plugins]") {
    Host h;
    h.plugins.load_by_name("wood");
    const FloorView view;

    SECTION("without turbulence the rings are circles 1 / rings apart") {
        const auto texture = wood(h, 2.0f, 0.0f);
        const Image image = view.render(h, lambert_with(h, texture));
        write_png(image, "plugin_wood_circles.png");
        // Every pixel is the texture at its hit point (classic Lambert, light straight down), except where
        // the renderer's and this test's hit points fall on two sides of a ring's edge.
        int differ = 0;
        for (int y = 0; y < 96; ++y) {
            for (int x = 0; x < 96; ++x) {
                TextureLookup q;
                q.point = view.hit(x, y);
                const RGB want = texture->eval(q), got = image.at(x, y);
                differ += std::abs(want.r - got.r) + std::abs(want.g - got.g) + std::abs(want.b - got.b) > 1e-4f;
            }
        }
        CHECK(differ <= 20);
        // Radii 0.5, 1, 1.5 and 2 on either side of the centre; the view reaches 2.18.
        CHECK(ring_edges(image, 47) == 8);
        CHECK(ring_edges(image, 20) == 4);  // |z| = 1.23: radii 1.5 and 2 on each side (the corner is at 2.5)
    }

    SECTION("turbulence moves the rings but keeps their number") {
        const Image image = view.render(h, lambert_with(h, wood(h, 2.0f, 0.3f)));
        write_png(image, "plugin_wood.png");
        const int edges = ring_edges(image, 47);
        CHECK(edges >= 7);
        CHECK(edges <= 9);
        const Image circles = view.render(h, lambert_with(h, wood(h, 2.0f, 0.0f)));
        int moved = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x) moved += !(image.at(x, y) == circles.at(x, y));
        CHECK(moved > 96 * 96 / 3);
    }

    SECTION("a texture from one module shades a material from another") {
        h.plugins.load_by_name("toon");
        const auto texture = wood(h, 2.0f, 0.3f);
        Params p;
        p.set_object<Texture>("color", std::const_pointer_cast<Texture>(texture));
        // Light straight down: n.l = 1, the top band, so the toon floor is the wood itself.
        const Image toon = view.render(h, h.materials.create("toon", p));
        const Image lambert = view.render(h, lambert_with(h, texture));
        int same = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x) same += toon.at(x, y) == lambert.at(x, y);
        CHECK(same == 96 * 96);
    }
}

TEST_CASE("an error thrown by a module's factory is caught as rtlab::Error by the host", "[plugins]") {
    Host h;
    h.plugins.load_by_name("toon");
    Params p;
    p.set("levels", 40.0);
    const std::string message = error_of([&] { (void)h.materials.create("toon", p); });
    CHECK_THAT(message, Catch::Contains("material 'toon'") && Catch::Contains("levels"));
    Params unused;
    unused.set("colour", 0.5);  // misspelt: the host's check of unused parameters names it
    CHECK_THAT(error_of([&] { (void)h.materials.create("toon", unused); }), Catch::Contains("colour"));
}

TEST_CASE("a module with a wrong record is refused naming the field, the expected and the found value", "[plugins]") {
    const RtlabPluginRecord host = make_plugin_record("");
    const std::string release = std::to_string(host.glibcxx_release);
    const std::string cxx11 = std::to_string(host.glibcxx_use_cxx11_abi);
    const std::string version = std::to_string(host.rtlab_version_major) + "." +
                                std::to_string(host.rtlab_version_minor) + "." +
                                std::to_string(host.rtlab_version_patch);
    const std::string next_version = std::to_string(host.rtlab_version_major) + "." +
                                     std::to_string(host.rtlab_version_minor + 1) + "." +
                                     std::to_string(host.rtlab_version_patch);
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
        {"abi",
         {"plugin ABI version: expected " + std::to_string(RTLAB_PLUGIN_ABI_VERSION) + ", got " +
          std::to_string(RTLAB_PLUGIN_ABI_VERSION + 98)}},  // plugins/wrong_record.cpp
        {"headers",
         {"public headers hash: expected '" + std::string(host.headers_hash) + "', got '" + std::string(64, '0') +
          "'"}},
        {"glibcxx", {"_GLIBCXX_RELEASE: expected " + release + ", got " + std::to_string(host.glibcxx_release - 1)}},
        {"cxx11_abi",
         {"_GLIBCXX_USE_CXX11_ABI: expected " + cxx11 + ", got " + (host.glibcxx_use_cxx11_abi == 0 ? "1" : "0")}},
        {"glm",
         {"GLM configuration: expected defaults, got GLM_CONFIG_ALIGNED_GENTYPES + GLM_FORCE_DEFAULT_ALIGNED_GENTYPES",
          "sizeof(Vec3): expected 12, got 16", "alignof(Vec4): expected 4, got 16"}},
        {"version", {"rtlab version: expected " + version + ", got " + next_version}},
    };
    REQUIRE(host.glm_config == 0);  // the expected text above assumes GLM's defaults for rtlab itself
    for (const auto& [field, wanted] : cases) {
        Host h;
        const fs::path file = module("rtlab_test_wrong_" + field);
        const std::string message = error_of([&] { h.plugins.load_file(file); });
        INFO(message);
        CHECK_THAT(message, Catch::StartsWith("plugin '" + file.string() + "' refused"));
        for (const std::string& w : wanted) CHECK_THAT(message, Catch::Contains(w));
        // One wrong field, one difference reported (the GLM case changes three fields together).
        CHECK(static_cast<std::size_t>(std::count(message.begin(), message.end(), ':')) == 1 + wanted.size());
        CHECK_THAT(message, !Catch::Contains("REGISTER CALLED"));
        CHECK(h.plugins.loaded().empty());
    }
}

TEST_CASE("a module registering a taken name is refused naming both owners and registers nothing", "[plugins]") {
    Host h;
    h.plugins.load_by_name("toon");
    const fs::path file = module("rtlab_test_duplicate");
    const std::string message = error_of([&] { h.plugins.load_file(file); });
    CHECK_THAT(message, Catch::StartsWith("plugin '" + file.string() + "' registers names that are taken"));
    CHECK_THAT(message,
               Catch::Contains("material 'toon' (already registered by plugin '" + example("toon").string() + "')"));
    CHECK_THAT(message, Catch::Contains("texture 'checker' (already registered by the built-ins)"));
    CHECK_THAT(message, !Catch::Contains("duplicate-only"));
    CHECK_FALSE(h.materials.contains("duplicate-only"));
    CHECK(h.plugins.loaded().size() == 1);

    // A clash inside one module is reported by its own registration.
    const std::string self = error_of([&] { h.plugins.load_file(module("rtlab_test_self_clash")); });
    CHECK_THAT(self, Catch::Contains("failed to register its types: material 'twice' is already registered"));
    CHECK_FALSE(h.materials.contains("twice"));
}

TEST_CASE("a scene's plugin name that is a path is refused", "[plugins]") {
    Host h;
    const std::vector<std::string> names{"../plugins/toon",
                                         "./toon.so",
                                         "sub/toon",
                                         "a\\toon",
                                         "..",
                                         "/abs/toon.so",
                                         (kExampleDir / "toon.so").string()};
    for (const std::string& name : names) {
        INFO(name);
        const std::string message = error_of([&] { h.plugins.load_by_name(name, "scene.json: plugins[0]"); });
        CHECK_THAT(message, Catch::StartsWith("scene.json: plugins[0]: plugin '" + name + "' is a path"));
        CHECK_THAT(message, Catch::Contains("by name only") && Catch::Contains(kExampleDir.string()));
    }
    CHECK(h.plugins.loaded().empty());
}

TEST_CASE("a plugin name not on the search path is refused naming where it was looked for", "[plugins]") {
    Host h(SearchPath({kModuleDir, kExampleDir}));
    const std::string message = error_of([&] { h.plugins.load_by_name("marble", "scene.json"); });
    CHECK_THAT(message, Catch::StartsWith("scene.json: plugin 'marble' not found on the plugin search path"));
    CHECK_THAT(message, Catch::Contains("'marble', 'marble.so', 'libmarble.so'"));
    CHECK_THAT(message, Catch::Contains("'" + kModuleDir.string() + "', '" + kExampleDir.string() + "'"));
    // The test modules are not in the build's plugin folder: only a folder on the path finds them.
    Host examples_only(SearchPath({kExampleDir}));
    CHECK_THAT(error_of([&] { examples_only.plugins.load_by_name("rtlab_test_duplicate"); }),
               Catch::Contains("not found"));
}

TEST_CASE("the plugin search path is --plugin-dir then RTLAB_PLUGIN_PATH then the installed folder", "[plugins]") {
    // The test runs from the build tree: bin/ beside lib/rtlab/plugins, as in an install.
    CHECK(fs::equivalent(installed_plugin_folder(), kExampleDir));
    ::setenv("RTLAB_PLUGIN_PATH", (kModuleDir.string() + ":/nowhere").c_str(), 1);
    const SearchPath path = plugin_search_path({"/first"});
    ::unsetenv("RTLAB_PLUGIN_PATH");
    REQUIRE(path.folders().size() == 4);
    CHECK(path.folders()[0] == "/first");
    CHECK(path.folders()[1] == kModuleDir);
    CHECK(path.folders()[2] == "/nowhere");
    CHECK(path.folders()[3] == installed_plugin_folder());

    // Found through the environment variable: a shared library, but not an rtlab plugin.
    Host h(path);
    CHECK_THAT(error_of([&] { h.plugins.load_by_name("rtlab_test_not_a_plugin"); }),
               Catch::Contains("is not an rtlab plugin: it does not export rtlab_plugin_query"));
    // The examples are found in the installed folder with no --plugin-dir and no variable.
    Host plain(plugin_search_path());
    CHECK(plain.plugins.load_by_name("wood").file == example("wood"));
}

TEST_CASE("a file that is missing or not a shared library is an error naming it", "[plugins]") {
    Host h;
    CHECK_THAT(error_of([&] { h.plugins.load_file("/nowhere/toon.so"); }),
               Catch::Contains("plugin '/nowhere/toon.so': file not found"));
    const fs::path text_file = fs::path(kModuleDir) / "not_a_library.so";
    {
        std::FILE* f = std::fopen(text_file.c_str(), "w");
        REQUIRE(f);
        std::fputs("not ELF\n", f);
        std::fclose(f);
    }
    CHECK_THAT(error_of([&] { h.plugins.load_file(text_file); }),
               Catch::Contains("plugin '" + fs::canonical(text_file).string() + "': cannot load"));
}

TEST_CASE("scenes/plugins.json loads toon and wood by name and matches its reference image", "[plugins]") {
    // The scene names its plugins; they are found on a search path holding only the examples' folder.
    SceneRegistries registries = SceneRegistries::builtins();
    PluginHost host(registries.materials, registries.textures, registries.lights, SearchPath({kExampleDir}));
    SceneLoadOptions options;
    options.use_environment = false;
    options.registries = &registries;
    options.plugin_loader = [&](const std::string& name) { host.load_by_name(name, "plugins.json"); };
    options.overrides.width = 64;
    options.overrides.height = 48;
    const fs::path source = RTLAB_SOURCE_DIR;
    const LoadedScene scene = load_scene(source / "scenes" / "plugins.json", options);
    CHECK(scene.plugins == std::vector<std::string>{"toon", "wood"});
    REQUIRE(host.loaded().size() == 2);
    const Image image = render_job(scene.job).image;
    const fs::path reference_file = source / "tests/scene/reference/plugins.pfm";
    if (std::getenv("RTLAB_UPDATE_REFERENCES")) write_image(image, reference_file);
    const Image reference = read_image(reference_file, ColorEncoding::linear);
    REQUIRE(reference.width() == 64);
    REQUIRE(reference.height() == 48);
    // Same build, same plugins, same seed: the image is the reference to within rounding of the PFM's floats.
    double worst = 0.0, sum = 0.0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) {
                worst = std::max(worst, double(std::abs(image.at(x, y)[c] - reference.at(x, y)[c])));
                sum += reference.at(x, y)[c];
            }
    INFO("worst channel difference " << worst << ", mean " << sum / (64 * 48 * 3));
    CHECK(worst <= 0.02);
    CHECK(sum / (64 * 48 * 3) > 0.2);  // neither black nor empty
}
