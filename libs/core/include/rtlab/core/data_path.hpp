#pragma once
/// \brief The one data lookup of apps and scene files: names relative to a data root ("models/stanford-bunny.obj",
/// "textures/earth.jpg") looked up, in this order, in
///   (a) a folder given per lookup (a scene file's folder; folder_of() makes a bare "still.json" mean "."),
///   (b) each --data-dir, (c) the ':'-separated folders of RTLAB_DATA_PATH,
///   (d) RTLAB_SHARED_DIR and the source checkout's ../shared (off when RTLAB_NO_SHARED=1),
///   (e) the files Debian data packages install for the name (the manifest, rtlab/core/asset_manifest.hpp).
/// Each answer says where the file came from and the credit that goes with it.
#include <rtlab/core/asset_manifest.hpp>
#include <rtlab/core/search_path.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// Names a folder laid out like ../shared (models/, textures/): searched after RTLAB_DATA_PATH.
inline constexpr std::string_view kSharedDirVariable = "RTLAB_SHARED_DIR";
/// When set to 1, neither RTLAB_SHARED_DIR nor the checkout's ../shared is searched: the data path is what a
/// user without ../shared has (--data-dir, RTLAB_DATA_PATH and the packages). The tests and CI use it.
inline constexpr std::string_view kNoSharedVariable = "RTLAB_NO_SHARED";

/// \brief A file found on the data path.
struct DataFile {
    std::filesystem::path path;
    std::string source;  ///< "--data-dir /x", "RTLAB_SHARED_DIR /y", "package glmark2-data", "folder ." ...
    std::string credit;  ///< from the manifest; empty for the user's own folders
};

/// \brief One folder of the data path and why it is there.
struct DataRoot {
    enum class Kind { data_dir, data_path_variable, shared };
    std::filesystem::path folder;
    Kind kind = Kind::data_dir;
    std::string origin;  ///< "--data-dir", "RTLAB_DATA_PATH", "RTLAB_SHARED_DIR", "../shared beside the checkout"
};

class DataPath {
public:
    /// The packages' files only (no folder): what a fresh machine without ../shared and without options has.
    DataPath() = default;
    /// `roots` in order (entries whose folder does not exist are left out and listed by missing_folders()),
    /// then the packages' files of `manifest` when `use_packages`.
    explicit DataPath(std::vector<DataRoot> roots, bool use_packages = true,
                      std::vector<AssetEntry> manifest = asset_manifest());

    /// The data path of a program: `data_dirs` (its --data-dir options), RTLAB_DATA_PATH, then, unless
    /// RTLAB_NO_SHARED=1, RTLAB_SHARED_DIR and the ../shared beside the source checkout that `executable`
    /// was built in (source_checkout()), then the packages.
    static DataPath from_environment(const std::vector<std::filesystem::path>& data_dirs,
                                     const std::filesystem::path& executable);

    /// Finds `name`: an absolute name as it is; a relative one in `first_folder` (when not empty), each
    /// root, then the manifest's package files for it. A directory is not a file.
    [[nodiscard]] std::optional<DataFile> find(const std::filesystem::path& name,
                                               const std::filesystem::path& first_folder = {}) const;
    /// Like find() for a folder (a cube map's faces); packages have none.
    [[nodiscard]] std::optional<std::filesystem::path> find_folder(
        const std::filesystem::path& name, const std::filesystem::path& first_folder = {}) const;
    /// Like find(), but a missing file is an rtlab::Error: "'NAME': file not found (looked in ...)".
    [[nodiscard]] DataFile require(const std::filesystem::path& name,
                                   const std::filesystem::path& first_folder = {}) const;

    /// Where a name is looked for, for messages: "'.', '/x' (--data-dir) and the files of the packages
    /// glmark2-data, openuniverse-common". Never empty: the packages are always named.
    [[nodiscard]] std::string describe(const std::filesystem::path& first_folder = {}) const;

    /// The --data-dir, RTLAB_DATA_PATH and RTLAB_SHARED_DIR folders that do not exist (programs warn, one line
    /// each).
    [[nodiscard]] const std::vector<DataRoot>& missing_folders() const { return m_missing; }
    [[nodiscard]] const std::vector<DataRoot>& roots() const { return m_roots; }

private:
    std::vector<DataRoot> m_roots;
    std::vector<DataRoot> m_missing;
    bool m_use_packages = true;
    std::vector<AssetEntry> m_manifest = asset_manifest();
};

/// The folder relative names in `file` (a scene file) are looked up in first: its parent, or "." for a bare
/// name such as "still.json" (whose parent_path() is empty).
std::filesystem::path folder_of(const std::filesystem::path& file);

/// The checkout an executable was built in (build/<preset>/bin/ lies inside it): the first folder above it
/// holding CMakePresets.json and libs/.
std::optional<std::filesystem::path> source_checkout(const std::filesystem::path& executable);

/// A warning line for each missing folder: "PROGRAM: warning: --data-dir '/x' does not exist".
std::vector<std::string> missing_folder_warnings(const DataPath& path, std::string_view program);

/// \brief One asset a program used: its logical name and the file found (nothing: a procedural stand-in).
struct AssetUse {
    std::string name;
    std::optional<DataFile> file;
};

/// One line for programs to print: "data: textures/earth.jpg, textures/mars.jpg from package
/// openuniverse-common; textures/sun.jpg procedural; credits: ...". Names are grouped by source in order
/// of first use; each credit is given once.
std::string describe_sources(const std::vector<AssetUse>& uses);

}  // namespace rtlab
