#pragma once
// Private to the scene loader: what the stages of loading one scene file share — its diagnostics, where its
// files are found, the named objects defined so far, and the scene being built.
#include <rtlab/core/data_path.hpp>
#include <rtlab/render/texture_level.hpp>
#include <rtlab/scene/scene_loader.hpp>
#include <rtlab/textures/mip_map.hpp>

#include "scene_json.hpp"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::scene_detail {

/// The categories of named objects; each has its own names and its own registry.
enum class Kind { texture, material, light, shape, tone, environment };
const char* kind_name(Kind kind);

/// A named object and where it was defined; a null object when building it failed (its error is reported
/// once, and references to it are not reported again).
template <class T>
struct Named {
    std::shared_ptr<T> object;
    std::string pointer;
};

template <class T>
std::vector<std::string> names_of(const std::map<std::string, Named<T>>& m) {
    std::vector<std::string> out;
    for (const auto& [k, v] : m) out.push_back(k);
    return out;
}

/// A texture with "lod": "auto" and what it is seen on.
struct AutoLevel {
    LevelOfDetail* levels = nullptr;
    std::vector<UvFootprint> users;
    bool environment = false;
};

class LoadContext {
public:
    LoadContext(const std::filesystem::path& file, const SceneLoadOptions& options, SceneRegistries& registries);

    Diagnostics diag;
    const SceneLoadOptions& options;
    SceneRegistries& registries;
    LoadedScene out;

    std::map<std::string, Named<Texture>> textures;
    std::map<std::string, Named<const Material>> materials;
    std::map<std::string, Named<const Light>> lights;
    std::map<std::string, Named<const Shape>> shapes;

    std::map<const Texture*, AutoLevel> auto_levels;
    /// The textures each texture and material uses, their own textures included: a shape using a material
    /// uses them all (for "lod": "auto").
    std::map<const Texture*, std::vector<const Texture*>> texture_uses;
    std::map<const Material*, std::vector<const Texture*>> material_uses;
    /// Where the textures the object being built uses are collected; nullptr when nothing collects.
    std::vector<const Texture*>* collecting = nullptr;
    void note_use(const Texture* texture);

    std::optional<CameraSpec> camera;  ///< with the final image size, once read

    void error(const std::string& pointer, const std::string& message) { diag.error(pointer, message); }
    /// A non-fatal problem, named by file and position like the errors.
    void warn(const std::string& pointer, const std::string& message);

    /// A file the scene names, found beside the scene or on the data path; nullopt (reported) otherwise.
    std::optional<std::string> find_file(const std::string& name, const std::string& pointer);
    std::optional<std::string> find_folder(const std::string& name, const std::string& pointer);
    /// Whether a file is found, and where a folder is, without reporting.
    bool has_file(const std::string& name) const;
    std::optional<std::string> locate_folder(const std::string& name) const;
    /// The scene file's folder ("." for a bare file name).
    const std::filesystem::path& folder() const { return m_folder; }
    /// "'scenes' (the scene's folder), '/data' ...": where files were looked for.
    std::string where() const;

private:
    std::filesystem::path m_folder;  ///< the scene file's folder ("." for a bare file name)
    DataPath m_data;
};

}  // namespace rtlab::scene_detail
