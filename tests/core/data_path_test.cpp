#include "rtlab/core/data_path.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <scratch_files.hpp>

#include "rtlab/core/error.hpp"

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) { return test::fresh_dir("rtlab_data_path_test_", name); }

using test::touch;

// A manifest of one package file that exists and one of a package that is not installed.
std::vector<AssetEntry> test_manifest(const fs::path& root) {
    touch(root / "pkg" / "bunny.obj");
    return parse_asset_manifest(
        "# comment\n\n"
        "models/bunny.obj\tpkg-a\t" +
            (root / "pkg" / "bunny.obj").string() +
            "\t3 triangles\tcredit A\n"
            "textures/earth.jpg\tpkg-b\t/nonexistent/earth.jpg\t2x1\tcredit B\n"
            "models/bunny.obj\tshared\tmodels/bunny.obj\t4 triangles\tcredit S\n",
        "test");
}

// Sets an environment variable for one scope.
struct ScopedEnv {
    std::string name;
    ScopedEnv(std::string n, const std::string& value) : name(std::move(n)) {
        ::setenv(name.c_str(), value.c_str(), 1);
    }
    ~ScopedEnv() { ::unsetenv(name.c_str()); }
};

}  // namespace

TEST_CASE("data path: the first folder then the roots in order then the packages", "[data_path]") {
    const fs::path root = fresh_dir("order");
    const auto manifest = test_manifest(root);
    touch(root / "scene" / "models" / "bunny.obj");
    touch(root / "dir" / "models" / "bunny.obj");
    touch(root / "shared" / "models" / "bunny.obj");
    const DataPath path({{root / "dir", DataRoot::Kind::data_dir, "--data-dir"},
                         {root / "shared", DataRoot::Kind::shared, "RTLAB_SHARED_DIR"}},
                        true, manifest);
    const auto first = path.find("models/bunny.obj", root / "scene");
    REQUIRE(first);
    CHECK(first->path == root / "scene" / "models" / "bunny.obj");
    const auto dir = path.find("models/bunny.obj");
    REQUIRE(dir);
    CHECK(dir->path == root / "dir" / "models" / "bunny.obj");
    CHECK(dir->source == "--data-dir " + (root / "dir").string());
    CHECK(dir->credit.empty());  // the user's own folder: no credit is known
    // A folder laid out like ../shared gets the manifest's "shared" credit.
    const auto shared = DataPath({{root / "shared", DataRoot::Kind::shared, "RTLAB_SHARED_DIR"}}, true, manifest)
                            .find("models/bunny.obj");
    REQUIRE(shared);
    CHECK(shared->credit == "credit S");
    const auto package = DataPath({}, true, manifest).find("models/bunny.obj");
    REQUIRE(package);
    CHECK(package->path == root / "pkg" / "bunny.obj");
    CHECK(package->source == "package pkg-a");
    CHECK(package->credit == "credit A");
    // A package that is not installed gives nothing; packages off give nothing.
    CHECK_FALSE(DataPath({}, true, manifest).find("textures/earth.jpg"));
    CHECK_FALSE(DataPath({}, false, manifest).find("models/bunny.obj"));
}

TEST_CASE("data path: absolute names folders and a bare scene path", "[data_path]") {
    const fs::path root = fresh_dir("kinds");
    touch(root / "a" / "f.png");
    fs::create_directories(root / "a" / "skybox");
    const DataPath path({{root / "a", DataRoot::Kind::data_dir, "--data-dir"}}, false);
    CHECK(path.find(root / "a" / "f.png")->path == root / "a" / "f.png");
    CHECK_FALSE(path.find(root / "a" / "missing.png"));
    CHECK_FALSE(path.find("skybox"));  // a directory is not a file
    CHECK_FALSE(path.find(""));
    CHECK(path.find_folder("skybox") == root / "a" / "skybox");
    CHECK_FALSE(path.find_folder("f.png"));
    // "still.json" in the current folder: its folder is ".", not an empty path that find() would skip.
    CHECK(folder_of("still.json") == fs::path("."));
    CHECK(folder_of("scenes/still.json") == fs::path("scenes"));
    const fs::path cwd = fs::current_path();
    fs::current_path(root / "a");
    const auto found = DataPath({}, false).find("f.png", folder_of("still.json"));
    fs::current_path(cwd);
    REQUIRE(found);
    CHECK(found->path == fs::path(".") / "f.png");
}

TEST_CASE("data path: missing folders are listed and messages name every place", "[data_path]") {
    const fs::path root = fresh_dir("messages");
    const auto manifest = test_manifest(root);
    fs::create_directories(root / "x");
    const DataPath path({{root / "x", DataRoot::Kind::data_dir, "--data-dir"},
                         {"/nonexistent-rtlab", DataRoot::Kind::data_dir, "--data-dir"}},
                        true, manifest);
    REQUIRE(path.missing_folders().size() == 1);
    CHECK(path.roots().size() == 1);
    const auto warnings = missing_folder_warnings(path, "rtlab-bunny");
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0] == "rtlab-bunny: warning: --data-dir '/nonexistent-rtlab' does not exist");
    CHECK(path.describe(".") == "'.', '" + (root / "x").string() +
                                    "' (--data-dir) and the files of the packages pkg-a; not installed: pkg-b "
                                    "(scripts/setup.sh installs them)");
    CHECK_THROWS_WITH(
        path.require("textures/earth.jpg"),
        Catch::StartsWith("'textures/earth.jpg': file not found (looked in '") && !Catch::Contains("no data folders"));
    // Never "in no data folders": the packages alone are named.
    CHECK(DataPath({}, true, manifest).describe().rfind("the files of the packages pkg-a", 0) == 0);
    CHECK(DataPath({}, false, manifest).describe().find("nowhere") == 0);
}

TEST_CASE("data path from the environment: options then RTLAB_DATA_PATH then RTLAB_SHARED_DIR", "[data_path]") {
    const fs::path root = fresh_dir("environment");
    fs::create_directories(root / "opt");
    fs::create_directories(root / "env");
    fs::create_directories(root / "shared");
    // The run "as a user would" sets RTLAB_NO_SHARED=1 for every test: this one sets it itself, below.
    const char* no_shared = std::getenv("RTLAB_NO_SHARED");
    const std::string saved = no_shared ? no_shared : "";
    ::unsetenv("RTLAB_NO_SHARED");
    const ScopedEnv data("RTLAB_DATA_PATH", (root / "env").string() + "::/nonexistent-env");
    const ScopedEnv shared("RTLAB_SHARED_DIR", (root / "shared").string());
    {
        const DataPath path = DataPath::from_environment({root / "opt", "/nonexistent-opt"}, "/usr/bin/x");
        REQUIRE(path.roots().size() == 3);
        CHECK(path.roots()[0].folder == root / "opt");
        CHECK(path.roots()[1].origin == "RTLAB_DATA_PATH");
        CHECK(path.roots()[2].origin == "RTLAB_SHARED_DIR");
        REQUIRE(path.missing_folders().size() == 2);
        CHECK(path.missing_folders()[0].folder == "/nonexistent-opt");
        CHECK(path.missing_folders()[1].folder == "/nonexistent-env");
    }
    {
        // RTLAB_NO_SHARED=1: what a user without ../shared has.
        const ScopedEnv off("RTLAB_NO_SHARED", "1");
        const DataPath path = DataPath::from_environment({}, "/usr/bin/x");
        REQUIRE(path.roots().size() == 1);
        CHECK(path.roots()[0].origin == "RTLAB_DATA_PATH");
    }
    if (no_shared) ::setenv("RTLAB_NO_SHARED", saved.c_str(), 1);
}

TEST_CASE("data path: the source checkout is found above the executable", "[data_path]") {
    const fs::path root = fresh_dir("checkout");
    touch(root / "repo" / "CMakePresets.json");
    fs::create_directories(root / "repo" / "libs");
    fs::create_directories(root / "repo" / "build" / "release" / "bin");
    CHECK(source_checkout(root / "repo" / "build" / "release" / "bin" / "rtlab-bunny") == root / "repo");
    CHECK_FALSE(source_checkout(root / "elsewhere" / "rtlab-bunny"));
}

TEST_CASE("data path: one line of sources and credits", "[data_path]") {
    const DataFile a{"/p/earth.jpg", "package pkg", "credit P"};
    const DataFile b{"/s/earth.jpg", "RTLAB_SHARED_DIR /s", "credit S"};
    const std::string line = describe_sources({{"textures/earth.jpg", a},
                                               {"textures/mars.jpg", a},
                                               {"textures/sun.jpg", std::nullopt},
                                               {"textures/venus.jpg", b}});
    CHECK(line ==
          "data: textures/earth.jpg, textures/mars.jpg from package pkg; textures/sun.jpg procedural; "
          "textures/venus.jpg from RTLAB_SHARED_DIR /s; credits: credit P; credit S");
}

TEST_CASE("the data manifest: five columns and absolute package files", "[data_path]") {
    CHECK_THROWS_WITH(parse_asset_manifest("a\tb\tc\n", "m.tsv"), Catch::StartsWith("m.tsv:1: expected 5"));
    CHECK_THROWS_WITH(parse_asset_manifest("#\na\tpkg\trelative.obj\t1 triangles\tc\n", "m.tsv"),
                      Catch::StartsWith("m.tsv:2: 'relative.obj'"));
    CHECK_THROWS_WITH(parse_asset_manifest("a\tpkg\t\t1 triangles\tc\n", "m.tsv"), Catch::Contains("empty column"));
    // The embedded one parses and names the two packages.
    const auto& manifest = asset_manifest();
    REQUIRE_FALSE(manifest.empty());
    bool glmark = false, openuniverse = false;
    for (const auto& e : manifest) {
        glmark = glmark || e.source == "glmark2-data";
        openuniverse = openuniverse || e.source == "openuniverse-common";
    }
    CHECK(glmark);
    CHECK(openuniverse);
}
