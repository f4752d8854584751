#pragma once
// Small files and folders that lookup tests make: an empty scratch folder per test and one-byte files in it.
#include <filesystem>
#include <fstream>
#include <string>

namespace rtlab::test {

/// An empty folder `prefix` + `name` under the temporary directory (removed first if it exists).
inline std::filesystem::path fresh_dir(const std::string& prefix, const std::string& name) {
    const std::filesystem::path d = std::filesystem::temp_directory_path() / (prefix + name);
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
