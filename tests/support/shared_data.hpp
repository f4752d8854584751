#pragma once
// Where tests find ../shared (real models and textures): the RTLAB_SHARED_DIR environment variable,
// else the folder CMake found at configure time. Tests that need it skip with a message when absent.
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace rtlab::test {

inline std::optional<std::filesystem::path> shared_dir() {
    const char* env = std::getenv("RTLAB_SHARED_DIR");
    std::filesystem::path dir = env && *env ? env : RTLAB_SHARED_DIR;
    if (dir.empty() || !std::filesystem::is_directory(dir / "models")) return std::nullopt;
    return dir;
}

/// A scratch folder for files a test writes, unique per test executable run.
inline std::filesystem::path scratch_dir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("rtlab_test_" + name);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace rtlab::test
