#pragma once
// Checks a registered type's declaration (Registry::spec) against its factory: built from the declared
// defaults (required keys given a sample value per kind), the factory reads every key it is given, looks up no
// key the declaration leaves out, and builds what it builds with those keys left out (the declared defaults
// are its own); each optional key without a default, given alone on top of that, is read too. Used for the
// built-in types (declarations_test.cpp) and the example plugins (plugin_test.cpp).
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/scene/scene_registries.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rtlab::test {

// A declared default as the value a loader hands a factory: "true", "0.5", "[0, 1, 0]" or a word.
inline Params::Value parse_default(const ParamSpec& p) {
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
inline double number_in_range(const ParamSpec& p) {
    if (p.lo <= 1.0 && 1.0 <= p.hi) return 1.0;
    return std::isfinite(p.lo) ? p.lo : p.hi;
}

// What the test gives a key that has no default: a value of its kind that a loader could hand over.
struct Samples {
    static std::filesystem::path scratch() {
        auto dir = std::filesystem::temp_directory_path() / "rtlab_test_declarations";
        std::filesystem::create_directories(dir);
        return dir;
    }

    std::filesystem::path dir = scratch();
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

inline std::vector<TypeSample> type_samples(const Samples& s) {
    return {
        {"texture", "image", {{"filename", s.image.string()}}, {"bake_size"}},
        {"texture", "cubemap", {{"folder", s.dir.string()}, {"extension", std::string("png")}}, {"bake_size"}},
        {"shape", "mesh", {{"filename", s.mesh.string()}}, {}},
        {"shape", "box", {{"max", Params::List{1.0, 1.0, 1.0}}}, {}},
        {"environment", "envmap", {{"filename", s.image.string()}}, {}},
    };
}

// What the factory looked up that the declaration does not have.
inline std::vector<std::string> undeclared(const Params& params, const TypeSpec& spec) {
    std::vector<std::string> out;
    for (const std::string& name : params.looked_up())
        if (!spec.find(name)) out.push_back(name);
    return out;
}

// What an object does, as numbers: two objects built from different parameter sets that give the same numbers
// took the same values (a declared default that is not the factory's own shows here).
// push_back, not insert of a braced list: GCC 12 warns falsely (stringop-overflow) on the latter.
inline void add(std::vector<float>& out, float a, float b, float c) {
    out.push_back(a);
    out.push_back(b);
    out.push_back(c);
}
inline void add(std::vector<float>& out, const RGB& c) { add(out, c.r, c.g, c.b); }
inline void add(std::vector<float>& out, const Vec3& v) { add(out, v.x, v.y, v.z); }

inline const TextureLookup kLookups[] = {
    {Vec2(0.1f, 0.2f), Point3(0.3f, -0.7f, 1.9f), Vec3(0.2f, 0.5f, 1.0f)},
    {Vec2(0.55f, 0.9f), Point3(-2.1f, 0.4f, 0.05f), Vec3(-1.0f, 0.1f, 0.3f)},
    {Vec2(0.97f, 0.43f), Point3(5.5f, 3.25f, -1.1f), Vec3(0.0f, -1.0f, 0.2f)},
    {Vec2(1.3f, -0.2f), Point3(0.01f, 0.02f, 0.03f), Vec3(0.4f, 0.4f, -1.0f)},
};

inline std::vector<float> behaviour(const Texture& t) {
    std::vector<float> out;
    for (const TextureLookup& q : kLookups) add(out, t.eval(q));
    return out;
}

inline std::vector<float> behaviour(const Material& m) {
    std::vector<float> out;
    add(out, m.ior_inside(), m.ior_outside(), m.fresnel() ? 1.0f : 0.0f);
    add(out, m.absorption());
    for (const TextureLookup& q : kLookups) {
        const SurfaceTerms t = m.terms(q);
        for (const RGB& c : {t.diffuse, t.specular, t.kr, t.kt, t.emission}) add(out, c);
        add(out, t.shape_u, t.shape_v, t.opacity);
        const Vec3 wo = glm::normalize(Vec3(0.3f, 0.1f, 0.9f)), wi = glm::normalize(Vec3(-0.2f, 0.4f, 0.8f));
        add(out, m.direct(t, wo, wi, Convention::physical));
        add(out, m.direct(t, wo, wi, Convention::classic));
    }
    return out;
}

inline std::vector<float> behaviour(const Light& light) {
    std::vector<float> out;
    out.push_back(static_cast<float>(light.sample_count()));
    add(out, light.ambient());
    for (const Point3& at : {Point3(0.5f, -3.0f, 0.2f), Point3(-1.0f, -0.5f, 2.0f)}) {
        const LightSample s = light.sample(at, 0, Vec2(0.3f, 0.6f), Convention::physical);
        add(out, s.wi);
        add(out, s.position);
        add(out, s.arriving);
    }
    return out;
}

inline std::vector<float> behaviour(const Shape& shape) {
    const AABB box = shape.bounds();
    std::vector<float> out;
    add(out, box.lo);
    add(out, box.hi);
    return out;
}

inline std::vector<float> behaviour(const EnvironmentEmitter& environment) {
    std::vector<float> out;
    for (const TextureLookup& q : kLookups) add(out, environment.radiance(q.direction));
    add(out, environment.power());
    return out;
}

inline std::vector<float> behaviour(const ToneOperator& op) {
    Image hdr(4, 2);
    for (int i = 0; i < 8; ++i) hdr.at(i % 4, i / 4) = RGB(0.01f * static_cast<float>(i * i + 1), 0.5f, 3.0f);
    std::vector<float> out;
    const Image shown = op.apply(hdr);  // kept: a loop over a temporary's pixels() would outlive it
    for (const RGB& c : shown.pixels()) add(out, c);
    return out;
}

/// Checks one type's declaration against its factory (see the top of the file).
template <class Base>
void check_type(const Registry<Base>& registry, const std::string& type, Samples& samples) {
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

    for (const ParamSpec& p : spec.params()) {
        INFO("parameter '" << p.name << "'");
        CHECK_FALSE(p.doc.empty());
        CHECK_FALSE((p.required && !p.default_value.empty()));
        if (p.kind == ParamKind::word) {
            CHECK_FALSE(p.words.empty());
            if (!p.default_value.empty())
                CHECK(std::find(p.words.begin(), p.words.end(), p.default_value) != p.words.end());
        }
    }
    // The declared defaults and the required keys' samples; without defaults, what the factory falls back on.
    auto fill = [&](Params& params, bool with_defaults) {
        samples.vectors = 0;
        for (const ParamSpec& p : spec.params()) {
            if (left_out(p.name)) continue;
            if (with_defaults && !p.default_value.empty())
                params.set(p.name, parse_default(p));
            else if (p.required)
                samples.set(params, p);
        }
        for (const auto& [name, value] : extra.give) params.set(name, value);
    };
    Params base, bare;
    fill(base, true);
    fill(bare, false);
    base.set_context(registry.category() + " '" + type + "'");

    // Every key given is read, and nothing undeclared is looked up.
    std::shared_ptr<Base> object;
    REQUIRE_NOTHROW(object = registry.factory(type)(base));
    CHECK(object != nullptr);
    CHECK_NOTHROW(base.check_all_used());
    CHECK(undeclared(base, spec) == std::vector<std::string>{});

    // The declared defaults are the factory's own: the same object as with the keys left out.
    std::shared_ptr<Base> by_factory;
    REQUIRE_NOTHROW(by_factory = registry.factory(type)(bare));
    CHECK(behaviour(*object) == behaviour(*by_factory));

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

/// check_type for every type of a registry.
template <class Base>
void check_registry(const Registry<Base>& registry, Samples& samples) {
    for (const std::string& type : registry.names()) check_type(registry, type, samples);
}

}  // namespace rtlab::test
