#include "options.hpp"

#include <catch2/catch.hpp>

#include <vector>

using namespace rtlab::app;

namespace {
std::optional<int> parse(std::vector<const char*> args, ViewOptions& o) {
    args.insert(args.begin(), "rtlab-view");
    return parse_view_options(static_cast<int>(args.size()), const_cast<char**>(args.data()), o);
}
}  // namespace

TEST_CASE("rtlab-view takes the scene then --screenshot-after-passes N FILE", "[view]") {
    ViewOptions o;
    REQUIRE_FALSE(parse({"scene.json", "--screenshot-after-passes", "3", "out.png"}, o));
    CHECK(o.scene == "scene.json");
    REQUIRE(o.screenshot_passes);
    CHECK(*o.screenshot_passes == 3);
    CHECK(o.screenshot_file == "out.png");
}

TEST_CASE("rtlab-view rejects a bad pass count and sampling it does not do", "[view]") {
    ViewOptions a, b, c;
    CHECK(parse({"scene.json", "--screenshot-after-passes", "0", "out.png"}, a) == kExitUsage);
    CHECK(parse({"scene.json", "--aa", "adaptive"}, b) == kExitUsage);
    CHECK(parse({}, c) == kExitUsage);
}

TEST_CASE("rtlab-view renders with the scene's integrator unless --integrator names one", "[view]") {
    ViewOptions a, b, c;
    REQUIRE_FALSE(parse({"scene.json"}, a));
    CHECK(a.integrator.empty());  // the worker then uses the file's
    REQUIRE_FALSE(parse({"scene.json", "--integrator", "path"}, b));
    CHECK(b.integrator == "path");
    CHECK(parse({"scene.json", "--integrator", "photons"}, c) == kExitUsage);
}
