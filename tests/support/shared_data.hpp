#pragma once
// Where tests find their data, pinned to one source so that a result does not depend on what else the machine
// has: "shared" is ../shared (RTLAB_SHARED_DIR, else the folder CMake found at configure time; never when
// RTLAB_NO_SHARED=1, the run "as a user would"), "packages" the files Debian data packages install (the
// manifest, data/assets.tsv). A test whose source is absent calls test::skip() (skip.hpp).
#include <rtlab/core/data_path.hpp>

#include "scratch_files.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace rtlab::test {

inline bool shared_disabled() {
    const char* off = std::getenv("RTLAB_NO_SHARED");
    return off && std::string(off) == "1";
}

inline std::optional<std::filesystem::path> shared_dir() {
    if (shared_disabled()) return std::nullopt;
    const char* env = std::getenv("RTLAB_SHARED_DIR");
    std::filesystem::path dir = env && *env ? env : RTLAB_SHARED_DIR;
    if (dir.empty() || !std::filesystem::is_directory(dir / "models")) return std::nullopt;
    return dir;
}

/// The message of a test skipped for want of ../shared.
inline std::string needs_shared(const std::string& what) {
    return what + " needs ../shared (set RTLAB_SHARED_DIR" + (shared_disabled() ? "; RTLAB_NO_SHARED=1 is set)" : ")");
}

enum class DataSource { shared, packages };

inline const char* source_name(DataSource s) { return s == DataSource::shared ? "shared" : "packages"; }

/// Whether every package file of the manifest is installed.
inline bool packages_installed() {
    for (const AssetEntry& e : asset_manifest())
        if (e.from_package() && !std::filesystem::is_regular_file(e.file)) return false;
    return true;
}

/// The data path of one source alone: ../shared without the packages, or the packages without any folder.
/// Nothing when that source is absent.
inline std::optional<DataPath> pinned_data_path(DataSource source) {
    if (source == DataSource::packages) {
        if (!packages_installed()) return std::nullopt;
        return DataPath({}, true);
    }
    const auto dir = shared_dir();
    if (!dir) return std::nullopt;
    return DataPath({{*dir, DataRoot::Kind::shared, "RTLAB_SHARED_DIR"}}, false);
}

/// A folder laid out like ../shared holding the source's files under their logical names: ../shared itself,
/// or for the packages a scratch folder of symbolic links to the packages' files (so that anything that takes
/// a data folder, a scene file's --data-dir, sees exactly the packages' data). Nothing when absent.
inline std::optional<std::filesystem::path> data_root(DataSource source) {
    if (source == DataSource::shared) return shared_dir();
    if (!packages_installed()) return std::nullopt;
    namespace fs = std::filesystem;
    const fs::path root = scratch_dir("package_data_root");
    std::vector<std::string> linked;  // the first installed candidate of a name wins, as in DataPath::find
    for (const AssetEntry& e : asset_manifest()) {
        if (!e.from_package() || !fs::is_regular_file(e.file)) continue;
        if (std::find(linked.begin(), linked.end(), e.name) != linked.end()) continue;
        linked.push_back(e.name);
        const fs::path link = root / e.name;
        std::error_code ec;
        if (fs::is_symlink(link, ec) && fs::read_symlink(link, ec) == e.file) continue;
        fs::create_directories(link.parent_path());
        // Tests in parallel processes make the same links: one of them wins, each ends with the right link.
        fs::remove(link, ec);
        fs::create_symlink(e.file, link, ec);
    }
    for (const AssetEntry& e : asset_manifest()) {
        std::error_code ec;
        if (e.from_package() && !fs::is_regular_file(root / e.name, ec)) return std::nullopt;
    }
    return root;
}

}  // namespace rtlab::test
