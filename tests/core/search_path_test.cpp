#include "rtlab/core/search_path.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <scratch_files.hpp>

#include "rtlab/core/error.hpp"

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) { return test::fresh_dir("rtlab_search_path_test_", name); }

using test::touch;

}  // namespace

TEST_CASE("the scene's folder comes first then the folders in order", "[search_path]") {
    const fs::path root = fresh_dir("order");
    touch(root / "scene" / "tex" / "a.png");
    touch(root / "one" / "tex" / "a.png");
    touch(root / "one" / "b.png");
    touch(root / "two" / "b.png");
    touch(root / "two" / "c.png");
    const SearchPath path({root / "one", root / "two"});
    CHECK(path.find("tex/a.png", root / "scene") == root / "scene" / "tex" / "a.png");
    CHECK(path.find("tex/a.png") == root / "one" / "tex" / "a.png");
    CHECK(path.find("b.png", root / "scene") == root / "one" / "b.png");
    CHECK(path.find("c.png") == root / "two" / "c.png");
    CHECK_FALSE(path.find("d.png").has_value());
    CHECK(path.find(root / "two" / "c.png") == root / "two" / "c.png");
}

TEST_CASE("folders and missing names are not files", "[search_path]") {
    const fs::path root = fresh_dir("dirs");
    fs::create_directories(root / "one" / "sub");
    const SearchPath path({root / "one"});
    CHECK_FALSE(path.find("sub").has_value());
    CHECK_FALSE(path.find("").has_value());
    CHECK_THROWS_WITH(path.require("sub"), Catch::Contains("'sub': file not found") && Catch::Contains("one"));
    // Only the folder given: it is named, and no "no folders" phrase follows it.
    CHECK_THROWS_WITH(SearchPath().require("x.png", root),
                      Catch::Contains("(looked in '" + root.string() + "')") && !Catch::Contains("no "));
    CHECK_THROWS_WITH(SearchPath().require("x.png"), Catch::Contains("no folder to look in was given"));
}

TEST_CASE("the environment variable adds folders after the explicit ones", "[search_path]") {
    const fs::path root = fresh_dir("env");
    touch(root / "env1" / "a.png");
    touch(root / "env2" / "b.png");
    touch(root / "cli" / "a.png");
    const std::string value = (root / "env1").string() + "::" + (root / "env2").string() + ":";
    ::setenv("RTLAB_SEARCH_PATH_TEST", value.c_str(), 1);
    const SearchPath path = SearchPath::from_environment({root / "cli"}, "RTLAB_SEARCH_PATH_TEST");
    ::unsetenv("RTLAB_SEARCH_PATH_TEST");
    REQUIRE(path.folders().size() == 3);
    CHECK(path.find("a.png") == root / "cli" / "a.png");
    CHECK(path.find("b.png") == root / "env2" / "b.png");
    CHECK(SearchPath::from_environment({}, "RTLAB_SEARCH_PATH_TEST_UNSET").folders().empty());
}
