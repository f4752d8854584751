// Declarations at work: a new type with a word parameter needs no edit of the loader; its errors point at
// the key; listings and the documentation's tables are made from the declarations.
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/scene/scene_loader.hpp>
#include <rtlab/scene/type_listing.hpp>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

using namespace rtlab;

namespace {

// A texture type of the kind a plugin adds: a word parameter, a number with a range, a colour or texture.
class Stripes final : public Texture {
public:
    Stripes(bool horizontal, float width) : m_horizontal(horizontal), m_width(width) {}
    RGB eval(const TextureLookup& q) const override {
        const float x = m_horizontal ? q.uv.y : q.uv.x;
        return RGB(static_cast<int>(x / m_width) % 2 ? 1.0f : 0.0f);
    }

private:
    bool m_horizontal;
    float m_width;
};

SceneRegistries with_stripes() {
    SceneRegistries r = SceneRegistries::builtins();
    TypeSpec spec("stripes across u or v");
    spec.add("direction", ParamKind::word, "which way the stripes run").allow({"across", "along"}).defaults("across");
    spec.add("width", ParamKind::number, "stripe width in uv units").range(1e-6, 1.0).defaults("0.1");
    r.textures.add(
        "stripes",
        [](const Params& p) {
            return std::make_shared<Stripes>(p.get_string("direction", "across") == "along",
                                             p.get_float("width", 0.1f));
        },
        std::move(spec));
    return r;
}

std::string scene_with(const std::string& texture) {
    return R"({"version": 1, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "textures": [)" +
           texture + R"(],
  "materials": [{"name": "m", "type": "lambert", "albedo": "s"}],
  "shapes": [{"type": "sphere", "material": "m"}]})";
}

}  // namespace

TEST_CASE("a new texture type with a word parameter loads through its declaration", "[scene_loader]") {
    SceneRegistries r = with_stripes();
    SceneLoadOptions options;
    options.registries = &r;
    const LoadedScene s = parse_scene(
        scene_with(R"({"name": "s", "type": "stripes", "direction": "along", "width": 0.25})"), "t.json", options);
    CHECK(s.job.scene->object_count() == 1);
}

TEST_CASE("an error in a new type's parameter points at the key's line and column", "[scene_loader]") {
    SceneRegistries r = with_stripes();
    SceneLoadOptions options;
    options.registries = &r;
    try {
        parse_scene(scene_with(R"({"name": "s", "type": "stripes",
      "direction": "alnog", "width": 2})"),
                    "t.json", options);
        FAIL("loaded");
    } catch (const Error& e) {
        const std::string msg = e.what();
        CHECK_THAT(msg, Catch::Contains("t.json:3:7: /textures/0/direction: unknown value 'alnog' for 'direction'; "
                                        "did you mean 'along'?"));
        CHECK_THAT(msg, Catch::Contains("t.json:3:29: /textures/0/width: must be in [1e-06, 1], not 2"));
    }
}

TEST_CASE("the verbose listing shows each type's keys and each shared group once", "[scene_loader]") {
    const SceneRegistries r = SceneRegistries::builtins();
    const std::string brief = list_types(r, false), verbose = list_types(r, true);
    CHECK_THAT(brief, Catch::Contains("materials:"));
    CHECK_THAT(verbose, Catch::Contains("every material also takes:"));
    // "kr" is declared once, in the group, not under each of the materials.
    std::size_t count = 0;
    for (std::size_t at = verbose.find("      kr ("); at != std::string::npos; at = verbose.find("      kr (", at + 1))
        ++count;
    CHECK(count == 1);
}

TEST_CASE("the parameter tables of docs/scene-format.md are the declarations'", "[scene_loader]") {
    const std::filesystem::path doc = std::filesystem::path(RTLAB_SOURCE_DIR) / "docs" / "scene-format.md";
    std::stringstream buffer;
    buffer << std::ifstream(doc).rdbuf();
    std::string text = buffer.str();
    const std::string begin = "<!-- generated: parameter tables (tests/scene/type_listing_test.cpp) -->\n",
                      end = "<!-- end of generated tables -->";
    const auto a = text.find(begin), b = text.find(end);
    REQUIRE(a != std::string::npos);
    REQUIRE(b != std::string::npos);
    const std::string expected = markdown_type_tables(SceneRegistries::builtins());
    const std::string current = text.substr(a + begin.size(), b - a - begin.size());
    if (current != expected && std::getenv("RTLAB_UPDATE_DOCS")) {
        text.replace(a + begin.size(), b - a - begin.size(), expected);
        std::ofstream(doc) << text;
        SUCCEED("docs/scene-format.md rewritten");
        return;
    }
    INFO("run this test with RTLAB_UPDATE_DOCS=1 to rewrite the tables from the declarations");
    CHECK(current == expected);
}
