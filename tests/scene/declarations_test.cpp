// Every built-in type's declaration against its factory (declaration_check.hpp): this keeps the declarations,
// which a scene loader checks a file's values by, from drifting from the code.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/scene/scene_registries.hpp>

#include <catch2/catch.hpp>

#include "declaration_check.hpp"

#include <string>
#include <vector>

using namespace rtlab;
using test::check_registry;
using test::Samples;
using test::undeclared;

TEST_CASE("every built-in type reads exactly the keys it declares", "[declarations]") {
    const SceneRegistries r = SceneRegistries::builtins();
    Samples samples;
    check_registry(r.shapes, samples);
    check_registry(r.materials, samples);
    check_registry(r.textures, samples);
    check_registry(r.lights, samples);
    check_registry(r.tone_operators, samples);
    check_registry(r.environments, samples);
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
