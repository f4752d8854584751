#include "rtlab/core/data_path.hpp"

#include <algorithm>
#include <cstdlib>
#include <system_error>

#include "rtlab/core/error.hpp"

namespace rtlab {

namespace fs = std::filesystem;

namespace {

// What is at `p` (not_found on any error): lookups ask this, never throw.
fs::file_type type_of(const fs::path& p) {
    std::error_code ec;
    return fs::status(p, ec).type();
}

bool is_file(const fs::path& p) { return type_of(p) == fs::file_type::regular; }
bool is_folder(const fs::path& p) { return type_of(p) == fs::file_type::directory; }

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

std::string environment(std::string_view name) {
    const char* value = std::getenv(std::string(name).c_str());
    return value ? value : "";
}

// The packages of the manifest, in order of first mention.
std::vector<std::string> package_names(const std::vector<AssetEntry>& manifest, bool installed) {
    std::vector<std::string> names;
    for (const AssetEntry& e : manifest) {
        if (!e.from_package() || std::find(names.begin(), names.end(), e.source) != names.end()) continue;
        const bool any_file = std::any_of(manifest.begin(), manifest.end(), [&](const AssetEntry& other) {
            return other.source == e.source && is_file(other.file);
        });
        if (any_file == installed) names.push_back(e.source);
    }
    return names;
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
    std::string out;
    for (const auto& s : items) out += (out.empty() ? "" : separator) + s;
    return out;
}

}  // namespace

DataPath::DataPath(std::vector<DataRoot> roots, bool use_packages, std::vector<AssetEntry> manifest)
    : m_use_packages(use_packages), m_manifest(std::move(manifest)) {
    for (DataRoot& r : roots) {
        if (r.folder.empty()) continue;
        (is_folder(r.folder) ? m_roots : m_missing).push_back(std::move(r));
    }
}

DataPath DataPath::from_environment(const std::vector<fs::path>& data_dirs, const fs::path& executable) {
    std::vector<DataRoot> roots;
    for (const fs::path& d : data_dirs) roots.push_back({d, DataRoot::Kind::data_dir, "--data-dir"});
    const SearchPath variable = SearchPath::from_environment({}, kDataPathVariable);
    for (const fs::path& d : variable.folders())
        roots.push_back({d, DataRoot::Kind::data_path_variable, std::string(kDataPathVariable)});
    if (environment(kNoSharedVariable) != "1") {
        if (const std::string shared = environment(kSharedDirVariable); !shared.empty())
            roots.push_back({shared, DataRoot::Kind::shared, std::string(kSharedDirVariable)});
        if (const auto checkout = source_checkout(executable)) {
            const fs::path shared = checkout->parent_path() / "shared";
            std::error_code ec;
            // Only when it exists: a checkout without ../shared beside it is the usual case, not a mistake.
            if (is_folder(shared))
                roots.push_back(
                    {fs::weakly_canonical(shared, ec), DataRoot::Kind::shared, "../shared beside the checkout"});
        }
    }
    return DataPath(std::move(roots));
}

std::optional<DataFile> DataPath::find(const fs::path& name, const fs::path& first_folder) const {
    if (name.empty()) return std::nullopt;
    if (name.is_absolute()) return is_file(name) ? std::optional(DataFile{name, "as given", {}}) : std::nullopt;
    if (!first_folder.empty() && is_file(first_folder / name))
        return DataFile{first_folder / name, "folder " + first_folder.string(), {}};
    for (const DataRoot& root : m_roots) {
        if (!is_file(root.folder / name)) continue;
        DataFile found{root.folder / name, root.origin + " " + root.folder.string(), {}};
        // A folder laid out like ../shared: its files are the ones the manifest's "shared" rows credit.
        if (root.kind == DataRoot::Kind::shared) {
            for (const AssetEntry& e : m_manifest)
                if (!e.from_package() && e.name == name.generic_string()) found.credit = e.credit;
        }
        return found;
    }
    if (m_use_packages) {
        for (const AssetEntry& e : m_manifest)
            if (e.from_package() && e.name == name.generic_string() && is_file(e.file))
                return DataFile{e.file, "package " + e.source, e.credit};
    }
    return std::nullopt;
}

std::optional<fs::path> DataPath::find_folder(const fs::path& name, const fs::path& first_folder) const {
    if (name.empty()) return std::nullopt;
    if (name.is_absolute()) return is_folder(name) ? std::optional(name) : std::nullopt;
    if (!first_folder.empty() && is_folder(first_folder / name)) return first_folder / name;
    for (const DataRoot& root : m_roots)
        if (is_folder(root.folder / name)) return root.folder / name;
    return std::nullopt;
}

DataFile DataPath::require(const fs::path& name, const fs::path& first_folder) const {
    if (auto found = find(name, first_folder)) return *found;
    if (name.is_absolute()) throw Error(quoted(name) + ": file not found (it does not exist or is not a file)");
    throw Error(quoted(name) + ": file not found (looked in " + describe(first_folder) + ")");
}

std::string DataPath::describe(const fs::path& first_folder) const {
    std::vector<std::string> places;
    if (!first_folder.empty()) places.push_back(quoted(first_folder));
    for (const DataRoot& r : m_roots) places.push_back(quoted(r.folder) + " (" + r.origin + ")");
    std::string packages;
    if (m_use_packages) {
        const auto installed = package_names(m_manifest, true), absent = package_names(m_manifest, false);
        if (!installed.empty()) packages = "the files of the packages " + join(installed, ", ");
        if (!absent.empty())
            packages += (packages.empty() ? "" : "; ") + std::string("not installed: ") + join(absent, ", ") +
                        " (scripts/setup.sh installs them)";
    }
    if (places.empty() && packages.empty()) return "nowhere: no data folder is given and the data packages are off";
    if (places.empty()) return packages;
    if (packages.empty()) return join(places, ", ");
    return join(places, ", ") + " and " + packages;
}

fs::path folder_of(const fs::path& file) { return file.has_parent_path() ? file.parent_path() : fs::path("."); }

std::optional<fs::path> source_checkout(const fs::path& executable) {
    std::error_code ec;
    for (fs::path dir = executable.parent_path(); !dir.empty(); dir = dir.parent_path()) {
        if (fs::is_regular_file(dir / "CMakePresets.json", ec) && is_folder(dir / "libs")) return dir;
        if (dir == dir.parent_path()) break;
    }
    return std::nullopt;
}

std::vector<std::string> missing_folder_warnings(const DataPath& path, std::string_view program) {
    std::vector<std::string> lines;
    for (const DataRoot& r : path.missing_folders())
        lines.push_back(std::string(program) + ": warning: " + r.origin + " " + quoted(r.folder) + " does not exist");
    return lines;
}

std::string describe_sources(const std::vector<AssetUse>& uses) {
    std::vector<std::pair<std::string, std::vector<std::string>>> groups;  // source -> names
    std::vector<std::string> credits;
    for (const AssetUse& use : uses) {
        const std::string source = use.file ? "from " + use.file->source : "procedural";
        auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == source; });
        if (group == groups.end()) group = groups.insert(groups.end(), {source, {}});
        group->second.push_back(use.name);
        if (use.file && !use.file->credit.empty() &&
            std::find(credits.begin(), credits.end(), use.file->credit) == credits.end())
            credits.push_back(use.file->credit);
    }
    std::vector<std::string> parts;
    for (const auto& [source, names] : groups) parts.push_back(join(names, ", ") + " " + source);
    std::string line = "data: " + join(parts, "; ");
    if (!credits.empty()) line += "; credits: " + join(credits, "; ");
    return line;
}

}  // namespace rtlab
