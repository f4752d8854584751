// The loader's defences against files no scene is: nesting, long keys, duplicate keys inside duplicates,
// objects with many keys. Each must end in one clear error (or load), in time linear in the file's size.
#include <rtlab/core/error.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <catch2/catch.hpp>
#include <scratch_files.hpp>

#include <filesystem>
#include <fstream>
#include <string>

using namespace rtlab;

namespace {

std::string load_error(const std::string& text) {
    try {
        parse_scene(text, "t.json");
    } catch (const Error& e) {
        return e.what();
    }
    FAIL("the scene loaded");
    return {};
}

const char* const kCameraAndSphere =
    R"("camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "render": {"width": 8, "height": 6},
       "materials": [{"name": "m", "type": "lambert"}],
       "shapes": [{"type": "sphere", "material": "m"}])";

}  // namespace

TEST_CASE("nesting deeper than the bound is refused at its first bracket too deep", "[scene_loader]") {
    // 100,000 brackets: the file the mutation run found taking over a minute.
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    const std::string msg = load_error(deep);
    CHECK_THAT(msg, Catch::Contains("nested more than 64 levels"));
    CHECK_THAT(msg, Catch::Contains("t.json:1:65"));
    // Inside a scene's own value, at the key that holds it.
    const std::string in_scene =
        R"({"version": 1, "description": )" + std::string(70, '[') + std::string(70, ']') + "}";
    CHECK_THAT(load_error(in_scene), Catch::Contains("nested more than 64 levels"));
}

TEST_CASE("nesting within the bound is an ordinary value", "[scene_loader]") {
    const std::string ok = R"({"version": 1, )" + std::string(kCameraAndSphere) + R"(, "description": )" +
                           std::string(60, '[') + std::string(60, ']') + "}";
    // Not a string: the description's type error, not a nesting error.
    const std::string msg = load_error(ok);
    CHECK_THAT(msg, Catch::Contains("/description: expected a string"));
    CHECK_THAT(msg, !Catch::Contains("nested"));
}

TEST_CASE("a key longer than the bound is refused", "[scene_loader]") {
    const std::string text = R"({"version": 1, ")" + std::string(100000, 'k') + R"(": 1})";
    CHECK_THAT(load_error(text), Catch::Contains("keys are at most 256 characters"));
}

TEST_CASE("duplicate keys inside the value of a duplicate key are reported once and do not crash", "[scene_loader]") {
    const std::string text = R"({"version": 1, )" + std::string(kCameraAndSphere) +
                             R"(, "description": "a", "description": {"x": {"y": 1, "y": 2}, "x": [1, {"z": 1}]}})";
    const std::string msg = load_error(text);
    CHECK_THAT(msg, Catch::Contains("duplicate key 'description'"));
    CHECK(msg.find("duplicate key 'y'") == std::string::npos);
}

TEST_CASE("an object with many keys gives one error per unknown key and loads", "[scene_loader]") {
    std::string text = R"({"version": 1, )" + std::string(kCameraAndSphere) + R"(, "render": {)";
    // 20,000 keys, the same one twice each: the duplicate check must not search the object from the start.
    for (int i = 0; i < 20000; ++i) text += (i ? ", " : "") + std::string("\"k") + std::to_string(i) + "\": 1";
    text += "}}";
    const std::string msg = load_error(text);
    CHECK_THAT(msg, Catch::Contains("duplicate key 'render'"));
}

TEST_CASE("a scene given by its bare file name finds files beside it in the current folder", "[scene_loader]") {
    const auto dir = test::scratch_dir("bare_scene");
    {
        std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        std::ofstream(dir / "still.json") << R"({"version": 1, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
            "materials": [{"name": "m", "type": "lambert"}],
            "shapes": [{"type": "mesh", "filename": "tri.obj", "material": "m"}]})";
    }
    const auto before = std::filesystem::current_path();
    std::filesystem::current_path(dir);
    LoadedScene s;
    REQUIRE_NOTHROW(s = load_scene("still.json"));
    std::filesystem::current_path(before);
    CHECK(s.job.scene->object_count() == 1);
}

TEST_CASE("an unknown key is told the nearest declared key", "[scene_loader]") {
    const std::string text = R"({"version": 1, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "materials": [{"name": "m", "type": "phong", "kdd": [1, 0, 0]}],
        "shapes": [{"type": "sphere", "material": "m"}]})";
    const std::string msg = load_error(text);
    CHECK_THAT(msg,
               Catch::Contains("/materials/0/kdd: unknown key 'kdd' for material type 'phong'; did you mean 'kd'?"));
    CHECK_THAT(msg, Catch::Contains("t.json:2:54"));
}

TEST_CASE("an unknown type is told the nearest registered type", "[scene_loader]") {
    const std::string text = R"({"version": 1, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "materials": [{"name": "m", "type": "lambrt"}], "shapes": [{"type": "sphere", "material": "m"}]})";
    CHECK_THAT(load_error(text), Catch::Contains("unknown material type 'lambrt'; did you mean 'lambert'?"));
}

TEST_CASE("a square pattern given a count that is not a square is told the nearest squares", "[scene_loader]") {
    const std::string text = R"({"version": 1, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "render": {"aa": "jittered", "spp": 10},
        "materials": [{"name": "m", "type": "lambert"}], "shapes": [{"type": "sphere", "material": "m"}]})";
    CHECK_THAT(load_error(text), Catch::Contains("/render/spp: 10 samples are not a square number, which jittered "
                                                 "needs: give 9 or 16"));
}
