#include "file_watch.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <thread>

using namespace rtlab::view;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("rtlab_view_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}
void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

/// Polls until the watch reports a change or `polls` reads found none (the quiet period is 0: the first read
/// that sees the event reports it).
bool changed(FileWatch& watch, int polls = 200) {
    for (int i = 0; i < polls; ++i) {
        if (watch.poll()) return true;
        std::this_thread::yield();
    }
    return false;
}
}  // namespace

TEST_CASE("the file watch sees writes in place and renames onto a watched file only", "[view]") {
    const fs::path dir = scratch("watch");
    write(dir / "scene.json", "{}");
    FileWatch watch(std::chrono::milliseconds(0));
    watch.watch({dir / "scene.json"});
    CHECK_FALSE(watch.poll());

    write(dir / "other.json", "{}");
    CHECK_FALSE(changed(watch));

    write(dir / "scene.json", "{\"version\": 1}");
    CHECK(changed(watch));
    CHECK_FALSE(watch.poll());  // reported once

    write(dir / "scene.json.tmp", "{\"version\": 1}");
    fs::rename(dir / "scene.json.tmp", dir / "scene.json");
    CHECK(changed(watch));
    fs::remove_all(dir);
}

TEST_CASE("the file watch waits for a quiet period before reporting", "[view]") {
    const fs::path dir = scratch("quiet");
    write(dir / "scene.json", "{}");
    FileWatch watch(std::chrono::hours(1));
    watch.watch({dir / "scene.json"});
    write(dir / "scene.json", "{\"version\": 1}");
    CHECK_FALSE(changed(watch));
    fs::remove_all(dir);
}
