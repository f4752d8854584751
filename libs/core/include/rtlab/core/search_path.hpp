#pragma once
/// \brief An ordered list of folders in which named files are looked up: data files named by scenes and
/// apps (textures, meshes) and plugin modules named by scenes.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// The environment variable holding extra data folders (separated by ':'), searched after --data-dir.
inline constexpr std::string_view kDataPathVariable = "RTLAB_DATA_PATH";

class SearchPath {
public:
    SearchPath() = default;
    /// Folders in the order given; empty entries are dropped.
    explicit SearchPath(std::vector<std::filesystem::path> folders);

    /// `explicit_folders` (command-line options) first, then the ':'-separated folders of the
    /// environment variable `variable`, if it is set.
    static SearchPath from_environment(std::vector<std::filesystem::path> explicit_folders, std::string_view variable);

    /// Appends a folder that is searched last.
    void append(std::filesystem::path folder);

    /// Finds `name`: an absolute name is taken as it is; a relative one is tried relative to `relative_to`
    /// first (when not empty: the folder of the scene file that names it), then in each folder in order.
    /// Returns the first regular file found, or nothing.
    [[nodiscard]] std::optional<std::filesystem::path> find(const std::filesystem::path& name,
                                                            const std::filesystem::path& relative_to = {}) const;

    /// Like find(), but a missing file is an rtlab::Error naming the file and every place that was tried.
    [[nodiscard]] std::filesystem::path require(const std::filesystem::path& name,
                                                const std::filesystem::path& relative_to = {}) const;

    [[nodiscard]] const std::vector<std::filesystem::path>& folders() const { return m_folders; }

    /// "'a', 'b'" or "no folders (none given)": for messages that say where a file was looked for.
    [[nodiscard]] std::string describe() const;

private:
    std::vector<std::filesystem::path> m_folders;
};

}  // namespace rtlab
