#include <rtlab/core/registry.hpp>

#include <catch2/catch.hpp>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {
struct Shape {
    virtual ~Shape() = default;
    virtual float size() const = 0;
};
struct Ball final : Shape {
    float radius;
    explicit Ball(float r) : radius(r) {}
    float size() const override { return radius; }
};
struct Cube final : Shape {
    float side;
    explicit Cube(float s) : side(s) {}
    float size() const override { return side; }
};

Registry<Shape> make_registry() {
    Registry<Shape> r("shape");
    TypeSpec ball("a ball");
    ball.add("radius", ParamKind::number, "its radius").defaults("1");
    r.add(
        "ball", [](const Params& p) { return std::make_shared<Ball>(p.get_float("radius", 1.0f)); }, ball);
    TypeSpec cube("a cube");
    cube.add("side", ParamKind::number, "its side").require();
    r.add(
        "cube", [](const Params& p) { return std::make_shared<Cube>(p.get_float("side")); }, cube);
    return r;
}
}  // namespace

TEST_CASE("registry creates by name with parameters and defaults", "[registry]") {
    const auto r = make_registry();
    CHECK(r.create("ball", Params{})->size() == 1.0f);
    CHECK(r.create("ball", Params{}.set("radius", 2.5))->size() == 2.5f);
    CHECK(r.create("cube", Params{}.set("side", 3.0))->size() == 3.0f);
    CHECK(r.names() == std::vector<std::string>{"ball", "cube"});
    CHECK(r.doc("ball") == "a ball");
    CHECK(r.spec("cube").names() == std::vector<std::string>{"side"});
}

TEST_CASE("unknown names list the known ones", "[registry]") {
    const auto r = make_registry();
    CHECK_THROWS_WITH(r.create("sphere", Params{}), Contains("unknown shape 'sphere'") && Contains("ball, cube"));
    Registry<Shape> empty("texture");
    CHECK_THROWS_WITH(empty.create("x", Params{}), Contains("none registered"));
}

TEST_CASE("missing or mistyped or unused parameters are errors naming the object", "[registry]") {
    const auto r = make_registry();
    CHECK_THROWS_WITH(r.create("cube", Params{}), Contains("shape 'cube'") && Contains("missing parameter 'side'"));
    CHECK_THROWS_WITH(r.create("cube", Params{}.set("side", std::string("big"))),
                      Contains("'side' must be a number") && Contains("not a string"));
    CHECK_THROWS_WITH(r.create("ball", Params{}.set("raduis", 2.0)),
                      Contains("shape 'ball'") && Contains("unused parameter(s) 'raduis'"));
}

TEST_CASE("duplicate registration is an error", "[registry]") {
    auto r = make_registry();
    CHECK_THROWS_WITH(r.add(
                          "ball", [](const Params&) { return std::make_shared<Ball>(1.0f); }, TypeSpec("a ball")),
                      Contains("already registered"));
}

TEST_CASE("params: typed getters", "[registry]") {
    Params p;
    p.set("n", 3.0).set("x", 0.5).set("flag", true).set("name", std::string("a")).set("v", Params::List{1, 2, 3});
    p.set_context("test 'p'");
    CHECK(p.get_int("n") == 3);
    CHECK_THROWS_WITH(p.get_int("x"), Contains("must be an integer"));
    CHECK(p.get_bool("flag", false));
    CHECK(p.get_string("name") == "a");
    CHECK(p.get_vec3("v") == Vec3(1, 2, 3));
    CHECK(p.get_rgb("v") == RGB(1, 2, 3));
    CHECK(p.get_rgb("x") == RGB(0.5f));
    CHECK_THROWS_WITH(p.get_vec3("x"), Contains("list of 3 numbers"));
    auto obj = std::make_shared<Ball>(4.0f);
    p.set_object<Shape>("inner", obj);
    CHECK(p.get_object<Shape>("inner")->size() == 4.0f);
    CHECK(p.get_object<Shape>("absent") == nullptr);
    CHECK_THROWS_WITH(p.get_object<Ball>("inner"), Contains("'inner' must be"));
    CHECK_NOTHROW(p.check_all_used());
}

TEST_CASE("params: get_value gives the raw value and marks it as read", "[registry]") {
    Params p;
    p.set("x", 0.5).set("s", std::string("word"));
    p.set_context("test 'p'");
    CHECK(p.get_value("absent") == nullptr);
    CHECK_THROWS_WITH(p.check_all_used(), Contains("'s', 'x'"));
    const Params::Value* x = p.get_value("x");
    REQUIRE(x != nullptr);
    CHECK(std::get<Params::Number>(*x) == 0.5);
    CHECK_THROWS_WITH(p.check_all_used(), Contains("'s'") && !Contains("'x'"));
    REQUIRE(p.get_value("s") != nullptr);
    CHECK(std::holds_alternative<std::string>(*p.get_value("s")));
    CHECK_NOTHROW(p.check_all_used());
}
