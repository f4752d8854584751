#pragma once
/// \brief Loading plugin modules: shared libraries that add materials, textures and lights to the host's
/// registries (docs/plugins.md; the boundary itself is rtlab/scene/plugin_abi.hpp).
#include <rtlab/core/search_path.hpp>
#include <rtlab/scene/plugin_abi.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/textures/texture.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// The environment variable holding extra plugin folders (separated by ':'), searched after --plugin-dir.
inline constexpr std::string_view kPluginPathVariable = "RTLAB_PLUGIN_PATH";

/// The installed plugin folder: <folder of the running executable>/../lib/rtlab/plugins (the relative part is
/// fixed when rtlab is configured, from its install directories). The build tree has the same layout, so
/// the programs of a build find that build's plugins.
std::filesystem::path installed_plugin_folder();

/// The plugin search path: `plugin_dirs` (--plugin-dir, in order), then the folders of RTLAB_PLUGIN_PATH,
/// then installed_plugin_folder().
SearchPath plugin_search_path(std::vector<std::filesystem::path> plugin_dirs = {});

/// Every field in which a module's record differs from the host's, as "<field>: expected <host's>, got
/// <module's>"; empty when they agree. A different abi_version or record_size stops the comparison there
/// (the rest of the record cannot be trusted to have the host's layout).
std::vector<std::string> plugin_record_differences(const RtlabPluginRecord& expected, const RtlabPluginRecord& got);

/// \brief One module that was loaded: where it came from and what it registered.
struct LoadedPlugin {
    std::filesystem::path file;  ///< as opened (canonical)
    std::string description;     ///< the module's own one line
    std::vector<std::string> materials, textures, lights;
};

/// \brief Loads plugin modules into one set of registries and remembers who registered which name.
///
/// Loading a module: dlopen(RTLD_NOW | RTLD_LOCAL) (every symbol resolves now, nothing leaks into other
/// modules), rtlab_plugin_query() and a check of every field of its record against this program's (a
/// mismatch is refused naming the file, the field, and the expected and found values), then
/// rtlab_plugin_register() into empty registries of the host's; only when every name it registered is new
/// are they moved into the host's registries, so a refused module leaves them as they were. A name that is
/// already taken is an error naming both the module and the earlier owner ("built-in" for a name that was in
/// the registries before the host saw it, else the module's file). Modules are never unloaded: their code
/// backs the objects and factories they made. Loading the same file twice is a no-op. Not thread-safe.
class PluginHost {
public:
    /// The registries must outlive the host and every object created from them.
    PluginHost(MaterialRegistry& materials, TextureRegistry& textures, LightRegistry& lights,
               SearchPath search_path = plugin_search_path());
    PluginHost(const PluginHost&) = delete;
    PluginHost& operator=(const PluginHost&) = delete;

    /// Loads the module at `file` (a path, as given on the command line: --plugin FILE.so).
    LoadedPlugin load_file(const std::filesystem::path& file);

    /// Loads the module a scene names. `name` is a name, never a path: "toon" is looked up as "toon",
    /// "toon.so" and "libtoon.so" in each folder of the search path. A name containing '/' or '\\' (or
    /// "." / ".."), or one not found, is an rtlab::Error that says so; `context` ("scene.json: plugins[0]")
    /// starts the message.
    LoadedPlugin load_by_name(std::string_view name, std::string_view context = {});

    /// Every module loaded, in load order.
    const std::vector<LoadedPlugin>& loaded() const { return m_loaded; }
    const SearchPath& search_path() const { return m_search_path; }

private:
    MaterialRegistry& m_materials;
    TextureRegistry& m_textures;
    LightRegistry& m_lights;
    SearchPath m_search_path;
    std::vector<LoadedPlugin> m_loaded;
    /// "material:toon" -> owner, for every name a module registered (names not here are built-in).
    std::map<std::string, std::string, std::less<>> m_owner;
};

}  // namespace rtlab
