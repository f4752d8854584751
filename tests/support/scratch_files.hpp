#pragma once
// Folders and files that tests write. ctest runs each test case as its own process, two at a time or more, so
// every path lives under a folder of this process (rtlab_test_<pid> in the temporary directory): two tests
// that pick the same name never see each other's files. The folder is removed when the process exits.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace rtlab::test {

/// This process's scratch folder, made on first use and removed at exit.
inline const std::filesystem::path& scratch_root() {
    struct Root {
        std::filesystem::path path =
            std::filesystem::temp_directory_path() / ("rtlab_test_" + std::to_string(::getpid()));
        Root() { std::filesystem::create_directories(path); }
        ~Root() {
            std::error_code ignored;  // a folder still open elsewhere is left for the system to clean
            std::filesystem::remove_all(path, ignored);
        }
    };
    static const Root root;
    return root.path;
}

/// A folder `name` in this process's scratch folder, made as needed (its files kept while the process runs).
inline std::filesystem::path scratch_dir(const std::string& name) {
    const std::filesystem::path d = scratch_root() / name;
    std::filesystem::create_directories(d);
    return d;
}

/// An empty folder `prefix` + `name` in this process's scratch folder (emptied first if it exists).
inline std::filesystem::path fresh_dir(const std::string& prefix, const std::string& name) {
    const std::filesystem::path d = scratch_root() / (prefix + name);
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

/// A one-byte file at `p`, its folders made as needed.
inline void touch(const std::filesystem::path& p) {
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << "x";
}

}  // namespace rtlab::test
