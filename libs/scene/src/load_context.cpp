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
        case Kind::environment:
            return "environment";
        default:
            return "shape";
    }
}

namespace {

DataPath data_path_of(const SceneLoadOptions& options) {
    if (options.data_path) return *options.data_path;
    if (options.use_environment) return DataPath::from_environment(options.data_dirs, {});
    std::vector<DataRoot> roots;
    for (const auto& dir : options.data_dirs) roots.push_back({dir, DataRoot::Kind::data_dir, "--data-dir"});
    return DataPath(std::move(roots), false);
}

}  // namespace

LoadContext::LoadContext(const fs::path& file, const SceneLoadOptions& load_options, SceneRegistries& reg)
    : diag(file.string()),
      options(load_options),
      registries(reg),
      m_folder(folder_of(file)),  // a bare "scene.json" lies in ".", which is searched (an empty folder is not)
      m_data(data_path_of(load_options)) {}

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
    return !name.empty() && m_data.find(name, m_folder).has_value();
}

std::optional<std::string> LoadContext::find_file(const std::string& name, const std::string& p) {
    if (name.empty()) {
        error(p, "expected a file name, not an empty string");
        return std::nullopt;
    }
    if (auto found = m_data.find(name, m_folder)) {
        out.assets.push_back({name, *found});
        return found->path.string();
    }
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
    if (name.empty()) return std::nullopt;
    if (auto found = m_data.find_folder(name, m_folder)) return found->string();
    return std::nullopt;
}

std::string LoadContext::where() const {
    return m_data.describe(m_folder) + "; add folders with --data-dir or " + std::string(kDataPathVariable);
}

}  // namespace rtlab::scene_detail
