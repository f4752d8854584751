#include "rtlab/core/search_path.hpp"

#include <cstdlib>
#include <system_error>

#include "rtlab/core/error.hpp"

namespace rtlab {

namespace fs = std::filesystem;

namespace {

bool is_file(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

}  // namespace

SearchPath::SearchPath(std::vector<fs::path> folders) {
    for (auto& f : folders) append(std::move(f));
}

SearchPath SearchPath::from_environment(std::vector<fs::path> explicit_folders, std::string_view variable) {
    SearchPath path(std::move(explicit_folders));
    if (const char* value = std::getenv(std::string(variable).c_str())) {
        const std::string_view list(value);
        std::size_t start = 0;
        while (start <= list.size()) {
            const std::size_t end = std::min(list.find(':', start), list.size());
            path.append(fs::path(list.substr(start, end - start)));
            start = end + 1;
        }
    }
    return path;
}

void SearchPath::append(fs::path folder) {
    if (!folder.empty()) m_folders.push_back(std::move(folder));
}

std::optional<fs::path> SearchPath::find(const fs::path& name, const fs::path& relative_to) const {
    if (name.empty()) return std::nullopt;
    if (name.is_absolute()) return is_file(name) ? std::optional(name) : std::nullopt;
    if (!relative_to.empty() && is_file(relative_to / name)) return relative_to / name;
    for (const fs::path& folder : m_folders) {
        if (is_file(folder / name)) return folder / name;
    }
    return std::nullopt;
}

fs::path SearchPath::require(const fs::path& name, const fs::path& relative_to) const {
    if (auto found = find(name, relative_to)) return *found;
    std::string tried;
    if (name.is_absolute()) {
        tried = "it does not exist or is not a file";
    } else if (relative_to.empty() && m_folders.empty()) {
        tried = "no folder to look in was given";
    } else {
        tried = "looked in ";
        if (!relative_to.empty()) tried += "'" + relative_to.string() + "'" + (m_folders.empty() ? "" : ", ");
        if (!m_folders.empty()) tried += describe();
    }
    throw Error("'" + name.string() + "': file not found (" + tried + ")");
}

std::string SearchPath::describe() const {
    if (m_folders.empty()) return "no folders (none given)";
    std::string out;
    for (const fs::path& f : m_folders) {
        if (!out.empty()) out += ", ";
        out += "'" + f.string() + "'";
    }
    return out;
}

}  // namespace rtlab
