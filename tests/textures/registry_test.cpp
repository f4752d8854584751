#include <rtlab/core/error.hpp>
#include <rtlab/textures/texture.hpp>

#include <catch2/catch.hpp>

#include "texture_lookup.hpp"

#include <cmath>

using namespace rtlab;
using Catch::Matchers::Contains;
using test::at_uv;

namespace {
// A texture the library does not know: defined and registered here, as a plugin module would do.
class StripesTexture final : public Texture {
public:
    StripesTexture(float period, RGB a, RGB b) : m_period(period), m_a(a), m_b(b) {}
    RGB eval(const TextureLookup& q) const override {
        return std::fmod(std::floor(q.uv.x / m_period), 2.0f) == 0.0f ? m_a : m_b;
    }

private:
    float m_period;
    RGB m_a, m_b;
};

void register_stripes(TextureRegistry& r) {
    TypeSpec spec("stripes along u");
    spec.add("period", ParamKind::number, "width of a pair of stripes").defaults("0.5");
    spec.add("a", ParamKind::colour, "the first stripe").defaults("1");
    spec.add("b", ParamKind::colour, "the second stripe").defaults("0");
    r.add(
        "stripes",
        [](const Params& p) -> std::shared_ptr<Texture> {
            return std::make_shared<StripesTexture>(p.get_float("period", 0.5f), p.get_rgb("a", RGB(1.0f)),
                                                    p.get_rgb("b", RGB(0.0f)));
        },
        spec);
}

}  // namespace

TEST_CASE("every built-in texture is registered with a documented parameter list", "[registry]") {
    const TextureRegistry r = make_texture_registry();
    const std::vector<std::string> expected{"checker", "checker3d", "cubemap", "image", "mandelbrot",
                                            "perlin",  "simplex",   "solid",   "stars"};
    CHECK(r.names() == expected);
    CHECK(r.category() == "texture");
    // Each declaration names the parameters with their defaults.
    auto listing = [&](const char* name) { return describe_params(r.spec(name), true); };
    CHECK_THAT(listing("solid"), Contains("color (colour, default 1)"));
    CHECK_THAT(listing("checker"), Contains("tiles_u (number, default 8") && Contains("tiles_v") &&
                                       Contains("color1 (colour or texture, default 1): even tiles") &&
                                       Contains("color2 (colour or texture, default 0): odd tiles"));
    CHECK_THAT(listing("checker3d"), Contains("tiles") &&
                                         Contains("color1 (colour or texture, default 1): even cells") &&
                                         Contains("color2 (colour or texture, default 0): odd cells"));
    CHECK_THAT(listing("mandelbrot"), Contains("iterations") && Contains("escape_radius") && Contains("center") &&
                                          Contains("zoom") && Contains("inside") && Contains("smooth"));
    for (const char* noise : {"perlin", "simplex"}) {
        CHECK_THAT(listing(noise), Contains("octaves (integer, default 6") && Contains("lacunarity") &&
                                       Contains("gain") && Contains("turbulence") && Contains("marble") &&
                                       Contains("color1 (colour or texture, default 0)"));
    }
    CHECK_THAT(listing("image"), Contains("filename (file)") && Contains("wrap (repeat | clamp | mirror") &&
                                     Contains("scale") && Contains("offset"));
    for (const char* face : {"px", "nx", "py", "ny", "pz", "nz", "cross"})
        CHECK(r.spec("cubemap").find(face)->kind == ParamKind::file);
    CHECK(r.spec("cubemap").find("folder")->kind == ParamKind::folder);
    CHECK(r.spec("cubemap").find("extension")->file_part);
}

TEST_CASE("a texture defined outside the library registers and nests like a built-in", "[registry]") {
    TextureRegistry r("texture");
    register_builtins(r);
    register_stripes(r);  // no edit to the library
    REQUIRE(r.contains("stripes"));
    const auto stripes = r.create("stripes", Params{}.set("period", 0.25).set("a", Params::List{0.0, 1.0, 0.0}));
    CHECK(stripes->eval(at_uv(0.1f, 0.0f)) == RGB(0.0f, 1.0f, 0.0f));
    CHECK(stripes->eval(at_uv(0.3f, 0.0f)) == RGB(0.0f));

    // Nested inside a built-in checker, passed as an object parameter.
    Params p;
    p.set("tiles_u", 1.0).set("tiles_v", 1.0).set("color2", 0.5);
    p.set_object<Texture>("color1", stripes);
    const auto checker = r.create("checker", p);
    CHECK(checker->eval(at_uv(0.1f, 0.5f)) == RGB(0.0f, 1.0f, 0.0f));  // tile (0, 0): stripes, first stripe
    CHECK(checker->eval(at_uv(0.3f, 0.5f)) == RGB(0.0f));              // tile (0, 0): stripes, second stripe
    CHECK(checker->eval(at_uv(1.1f, 0.5f)) == RGB(0.5f));              // tile (1, 0): colour 2

    CHECK_THROWS_WITH(
        r.add(
            "stripes", [](const Params&) { return std::shared_ptr<Texture>{}; }, TypeSpec("stripes again")),
        Contains("already registered"));
}

TEST_CASE("parameter errors name the texture and the parameter", "[registry]") {
    const TextureRegistry r = make_texture_registry();
    CHECK_THROWS_WITH(r.create("checker", Params{}.set("tiles", 4.0)),
                      Contains("texture 'checker'") && Contains("'tiles'"));
    CHECK_THROWS_WITH(r.create("checker", Params{}.set("tiles_u", -1.0)),
                      Contains("texture 'checker'") && Contains("'tiles_u' must be finite and > 0"));
    CHECK_THROWS_WITH(r.create("checker", Params{}.set("tiles_u", std::string("many"))),
                      Contains("'tiles_u' must be a number"));
    // The old two-key form (color1 or texture1) is gone: texture1 is an unknown parameter.
    Params old;
    old.set_object<Texture>("texture1", r.create("solid", Params{}));
    CHECK_THROWS_WITH(r.create("checker", old),
                      Contains("texture 'checker'") && Contains("unused parameter(s) 'texture1'"));
    CHECK_THROWS_WITH(r.create("checker", Params{}.set("color2", std::string("red"))),
                      Contains("texture 'checker': parameter 'color2' must be a colour (one number or a list of 3) or "
                               "a texture, not a string"));
    CHECK_THROWS_WITH(r.create("checker3d", Params{}.set("color1", Params::List{0.0, 1e300, 0.0})),
                      Contains("texture 'checker3d': parameter 'color1' must be finite"));
    CHECK_THROWS_WITH(
        r.create("simplex", Params{}.set("color2", Params::List{0.5, 0.5})),
        Contains("texture 'simplex': parameter 'color2' must be a colour") && Contains("a list of 2 numbers"));
    CHECK_THROWS_WITH(r.create("mandelbrot", Params{}.set("escape_radius", 1.5)),
                      Contains("'escape_radius' must be >= 2"));
    CHECK_THROWS_WITH(r.create("mandelbrot", Params{}.set("iterations", 0.0)), Contains("'iterations' must be in [1"));
    CHECK_THROWS_WITH(r.create("mandelbrot", Params{}.set("center", Params::List{1, 2, 3})), Contains("'center'"));
    CHECK_THROWS_WITH(
        r.create("perlin", Params{}.set("pattern", std::string("wood"))),
        Contains("texture 'perlin'") && Contains("'pattern' must be one of noise, fbm, turbulence, marble"));
    CHECK_THROWS_WITH(r.create("simplex", Params{}.set("dimension", 4.0)), Contains("'dimension' must be in [2, 3]"));
    CHECK_THROWS_WITH(r.create("perlin", Params{}.set("octaves", 2.5)), Contains("'octaves' must be an integer"));
    CHECK_THROWS_WITH(r.create("solid", Params{}.set("color", Params::List{1, 2})),
                      Contains("'color' must be a colour"));
    CHECK_THROWS_WITH(r.create("solid", Params{}.set("colour", 1.0)), Contains("unused parameter(s) 'colour'"));
    CHECK_THROWS_WITH(r.create("solid", Params{}.set("color", 1e300)), Contains("'color' must be finite"));
    CHECK_THROWS_WITH(r.create("image", Params{}),
                      Contains("texture 'image'") && Contains("missing parameter 'filename'"));
    CHECK_THROWS_WITH(
        r.create("image", Params{}.set("filename", std::string("x.png")).set("wrap", std::string("tile"))),
        Contains("'wrap' must be one of repeat, clamp, mirror"));
    CHECK_THROWS_WITH(r.create("cubemap", Params{}), Contains("texture 'cubemap'") && Contains("exactly one"));
    CHECK_THROWS_WITH(r.create("cubemap", Params{}.set("px", std::string("a.png"))), Contains("'nx' is missing"));
    CHECK_THROWS_WITH(r.create("nosuch", Params{}), Contains("unknown texture 'nosuch'") && Contains("checker"));
}

TEST_CASE("solid gives its colour for every lookup", "[registry]") {
    const TextureRegistry r = make_texture_registry();
    CHECK(r.create("solid", Params{})->eval({}) == RGB(1.0f));
    const auto t = r.create("solid", Params{}.set("color", Params::List{0.25, 0.5, 2.0}));
    TextureLookup q;
    q.uv = {-7.0f, 1e6f};
    q.point = {1.0f, 2.0f, 3.0f};
    CHECK(t->eval(q) == RGB(0.25f, 0.5f, 2.0f));
}
