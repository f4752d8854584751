// Every built-in type's declaration (Registry::spec) against its factory: built from the declared defaults
// (required keys given a sample value per kind), the factory reads every key it is given and looks up no key
// the declaration leaves out; each optional key without a default, given alone on top of that, is read too.
// This keeps the declarations, which a scene loader checks a file's values by, from drifting from the code.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/scene/scene_registries.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

// A declared default as the value a loader hands a factory: "true", "0.5", "[0, 1, 0]" or a word.
Params::Value parse_default(const ParamSpec& p) {
    const std::string& text = p.default_value;
    if (p.kind == ParamKind::boolean) return text == "true";
    if (p.kind == ParamKind::word || p.kind == ParamKind::text) return text;
    if (text.front() == '[') {
        Params::List list;
        std::istringstream in(text.substr(1));
        double x = 0.0;
        char separator = 0;
        while (in >> x) {
            list.push_back(x);
            in >> separator;
        }
        return list;
    }
    return std::stod(text);
}

// A number inside the declared range: 1 when the range holds it, else its finite end.
double number_in_range(const ParamSpec& p) {
    if (p.lo <= 1.0 && 1.0 <= p.hi) return 1.0;
    return std::isfinite(p.lo) ? p.lo : p.hi;
}

// What the test gives a key that has no default: a value of its kind that a loader could hand over.
struct Samples {
    std::filesystem::path dir = test::scratch_dir("declarations");
    std::filesystem::path image = dir / "px.png";
    std::filesystem::path mesh = dir / "triangle.obj";
    std::shared_ptr<Texture> texture = make_texture_registry().create("solid", Params{});
    std::shared_ptr<const Shape> shape = std::make_shared<Sphere>(Point3(0.0f), 1.0f);
    int vectors = 0;  // required vectors get distinct axes, so that quads and triangles are not degenerate

    Samples() {
        // Six small faces (px.png ... nz.png) for a cubemap's folder, one of them the image sample too.
        for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"})
            write_image(Image(4, 4, RGB(0.5f)), dir / (std::string(face) + ".png"));
        std::ofstream(mesh) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    }

    void set(Params& params, const ParamSpec& p) {
        switch (p.kind) {
            case ParamKind::number:
            case ParamKind::integer:
                params.set(p.name, number_in_range(p));
                return;
            case ParamKind::boolean:
                params.set(p.name, true);
                return;
            case ParamKind::colour:
                params.set(p.name, 0.5);
                return;
            case ParamKind::vector: {
                static const Params::List axes[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
                params.set(p.name, axes[vectors++ % 4]);
                return;
            }
            case ParamKind::numbers:
                params.set(p.name, Params::List{1.0});
                return;
            case ParamKind::texture:
            case ParamKind::scalar:
                params.set_object<Texture>(p.name, texture);
                return;
            case ParamKind::file:
                params.set(p.name, image.string());
                return;
            case ParamKind::folder:
                params.set(p.name, dir.string());
                return;
            case ParamKind::word:
                params.set(p.name, p.words.empty() ? std::string("x") : p.words.front());
                return;
            case ParamKind::text:
                params.set(p.name, std::string("png"));
                return;
            case ParamKind::shape:
                params.set_object<const Shape>(p.name, shape);
                return;
        }
    }
};

// Where a declaration alone cannot make a complete set: a file of the type's own format, one of several
// sources (a cubemap's faces, cross, folder or bake; an image's filename or bake), two values in order.
// `give` is set after the defaults, `leave_out` are defaults left out (keys only used with another).
struct TypeSample {
    std::string category, type;
    std::vector<std::pair<std::string, Params::Value>> give;
    std::vector<std::string> leave_out;
};

std::vector<TypeSample> type_samples(const Samples& s) {
    return {
        {"texture", "image", {{"filename", s.image.string()}}, {"bake_size"}},
        {"texture", "cubemap", {{"folder", s.dir.string()}, {"extension", std::string("png")}}, {"bake_size"}},
        {"shape", "mesh", {{"filename", s.mesh.string()}}, {}},
        {"shape", "box", {{"max", Params::List{1.0, 1.0, 1.0}}}, {}},
    };
}

// What the factory looked up that the declaration does not have.
std::vector<std::string> undeclared(const Params& params, const TypeSpec& spec) {
    std::vector<std::string> out;
    for (const std::string& name : params.looked_up())
        if (!spec.find(name)) out.push_back(name);
    return out;
}

template <class Base>
void check_registry(const Registry<Base>& registry, Samples& samples) {
    for (const std::string& type : registry.names()) {
        const TypeSpec& spec = registry.spec(type);
        INFO(registry.category() << " '" << type << "'");
        CHECK_FALSE(spec.doc().empty());
        samples.vectors = 0;

        TypeSample extra;
        for (const TypeSample& t : type_samples(samples))
            if (t.category == registry.category() && t.type == type) extra = t;
        auto left_out = [&](const std::string& name) {
            return std::find(extra.leave_out.begin(), extra.leave_out.end(), name) != extra.leave_out.end();
        };

        Params base;
        for (const ParamSpec& p : spec.params()) {
            INFO("parameter '" << p.name << "'");
            CHECK_FALSE(p.doc.empty());
            CHECK_FALSE((p.required && !p.default_value.empty()));
            if (p.kind == ParamKind::word) {
                CHECK_FALSE(p.words.empty());
                if (!p.default_value.empty())
                    CHECK(std::find(p.words.begin(), p.words.end(), p.default_value) != p.words.end());
            }
            if (left_out(p.name)) continue;
            if (!p.default_value.empty())
                base.set(p.name, parse_default(p));
            else if (p.required)
                samples.set(base, p);
        }
        for (const auto& [name, value] : extra.give) base.set(name, value);
        base.set_context(registry.category() + " '" + type + "'");

        // Every key given is read, and nothing undeclared is looked up.
        std::shared_ptr<Base> object;
        REQUIRE_NOTHROW(object = registry.factory(type)(base));
        CHECK(object != nullptr);
        CHECK_NOTHROW(base.check_all_used());
        CHECK(undeclared(base, spec) == std::vector<std::string>{});

        // Each declared key left out above, given alone: read (an error about its value is fine: a cubemap
        // refuses a second source), never unused; and still nothing undeclared looked up.
        for (const ParamSpec& p : spec.params()) {
            if (base.has(p.name)) continue;
            INFO("with '" << p.name << "' given too");
            Params one = base;
            samples.set(one, p);
            bool built = false;
            try {
                registry.factory(type)(one);
                built = true;
            } catch (const ParamError& e) {
                CHECK(e.reason() != ParamError::Reason::unused);
            } catch (const Error&) {
            }
            if (built) CHECK_NOTHROW(one.check_all_used());
            const std::vector<std::string> looked = one.looked_up();
            CHECK(std::find(looked.begin(), looked.end(), p.name) != looked.end());
            CHECK(undeclared(one, spec) == std::vector<std::string>{});
        }
    }
}

}  // namespace

TEST_CASE("every built-in type reads exactly the keys it declares", "[declarations]") {
    const SceneRegistries r = SceneRegistries::builtins();
    Samples samples;
    check_registry(r.shapes, samples);
    check_registry(r.materials, samples);
    check_registry(r.textures, samples);
    check_registry(r.lights, samples);
    check_registry(r.tone_operators, samples);
}

TEST_CASE("a factory reading an undeclared key is caught", "[declarations]") {
    // The check above sees what a factory looks up, given or not: here "radius" read but not declared.
    ShapeRegistry shapes("shape");
    shapes.add(
        "ball",
        [](const Params& p) -> std::shared_ptr<Shape> {
            return std::make_shared<Sphere>(Point3(0.0f), p.get_float("radius", 1.0f));
        },
        TypeSpec("a ball that forgot to declare its radius"));
    Params p;
    shapes.factory("ball")(p);
    CHECK(undeclared(p, shapes.spec("ball")) == std::vector<std::string>{"radius"});
}

TEST_CASE("every material declares the shared keys once as one group", "[declarations]") {
    const MaterialRegistry materials = make_material_registry();
    for (const std::string& type : materials.names()) {
        INFO(type);
        for (const ParamSpec& shared : material_shared_params()) {
            const ParamSpec* p = materials.spec(type).find(shared.name);
            REQUIRE(p != nullptr);
            CHECK(p->group == "material");
            CHECK(p->kind == shared.kind);
        }
        // The type's own keys come first and are not in the group; the doc no longer repeats the shared keys.
        CHECK(materials.spec(type).doc().find("opacity") == std::string::npos);
    }
    // Types whose defaults of shared keys differ say so.
    CHECK(materials.spec("glass").find("kr")->default_value == "1");
    CHECK(materials.spec("glass").find("fresnel")->default_value == "true");
    CHECK(materials.spec("cook-torrance").find("ior")->default_value == "1.5");
    CHECK(materials.spec("lambert").find("kr")->default_value == "0");
}

TEST_CASE("the mesh's accel words are the accelerator names", "[declarations]") {
    const ShapeRegistry shapes = make_shape_registry();
    const ParamSpec* accel = shapes.spec("mesh").find("accel");
    REQUIRE(accel != nullptr);
    CHECK(accel->words == accelerator_methods());
}
