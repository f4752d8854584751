#include "load_context.hpp"

#include <system_error>

namespace rtlab::scene_detail {

namespace fs = std::filesystem;

const char* kind_name(Kind k) {
    switch (k) {
        case Kind::texture:
            return "texture";
        case Kind::material:
            return "material";
        case Kind::light:
            return "light";
        case Kind::tone:
            return "tone operator";
        default:
            return "shape";
    }
}

LoadContext::LoadContext(const fs::path& file, const SceneLoadOptions& load_options, SceneRegistries& reg)
    : diag(file.string()),
      options(load_options),
      registries(reg),
      // A bare "scene.json" lies in the current folder: "." is searched, where an empty folder would be skipped.
      m_folder(file.has_parent_path() ? file.parent_path() : fs::path(".")) {
    m_search = options.use_environment ? SearchPath::from_environment(options.data_dirs, kDataPathVariable)
                                       : SearchPath(options.data_dirs);
}

void LoadContext::note_use(const Texture* texture) {
    if (!collecting || !texture) return;
    collecting->push_back(texture);
    if (auto it = texture_uses.find(texture); it != texture_uses.end())
        collecting->insert(collecting->end(), it->second.begin(), it->second.end());
}

void LoadContext::warn(const std::string& p, const std::string& message) {
    const std::string pos = diag.position(p);
    out.warnings.push_back(diag.file() + (pos.empty() ? "" : ":" + pos) + ": " + p + ": " + message);
}

bool LoadContext::has_file(const std::string& name) const {
    return !name.empty() && m_search.find(name, m_folder).has_value();
}

std::optional<std::string> LoadContext::find_file(const std::string& name, const std::string& p) {
    if (name.empty()) {
        error(p, "expected a file name, not an empty string");
        return std::nullopt;
    }
    if (auto found = m_search.find(name, m_folder)) return found->string();
    std::error_code ec;
    const fs::path beside = m_folder / name;
    if (fs::is_directory(fs::path(name).is_absolute() ? fs::path(name) : beside, ec)) {
        error(p, "'" + name + "' is a directory, not a file");
        return std::nullopt;
    }
    error(p, "file '" + name + "' not found (looked in " + where() + ")");
    return std::nullopt;
}

std::optional<std::string> LoadContext::find_folder(const std::string& name, const std::string& p) {
    if (auto found = locate_folder(name)) return found;
    error(p, "folder '" + name + "' not found (looked in " + where() + ")");
    return std::nullopt;
}

std::optional<std::string> LoadContext::locate_folder(const std::string& name) const {
    std::error_code ec;
    std::vector<fs::path> tries;
    if (fs::path(name).is_absolute()) {
        tries.push_back(name);
    } else {
        tries.push_back(m_folder / name);
        for (const auto& f : m_search.folders()) tries.push_back(f / name);
    }
    for (const auto& t : tries)
        if (!name.empty() && fs::is_directory(t, ec)) return t.string();
    return std::nullopt;
}

std::string LoadContext::where() const {
    std::string out = "'" + m_folder.string() + "' (the scene's folder)";
    for (const auto& f : m_search.folders()) out += ", '" + f.string() + "'";
    if (m_search.folders().empty()) out += "; add folders with --data-dir or " + std::string(kDataPathVariable);
    return out;
}

}  // namespace rtlab::scene_detail
