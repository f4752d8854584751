// PluginHost: finding, opening, checking and registering plugin modules.
#include <rtlab/core/error.hpp>
#include <rtlab/scene/plugin.hpp>

#include <dlfcn.h>

#include <array>
#include <system_error>

#ifndef RTLAB_PLUGIN_DIR_FROM_BINDIR
#error "RTLAB_PLUGIN_DIR_FROM_BINDIR (the installed plugin folder relative to the programs) must be defined"
#endif

namespace rtlab {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

std::string dl_error() {
    const char* e = dlerror();
    return e ? e : "unknown error";
}

/// The module's registrations of one category: a name taken already is a clash naming its owner.
template <class Base>
void find_clashes(const Registry<Base>& staged, const Registry<Base>& host,
                  const std::map<std::string, std::string, std::less<>>& owner, std::vector<std::string>& clashes) {
    for (const std::string& name : staged.names()) {
        if (!host.contains(name)) continue;
        const auto it = owner.find(host.category() + ":" + name);
        const std::string by = it == owner.end() ? "the built-ins" : "plugin " + it->second;
        clashes.push_back(host.category() + " '" + name + "' (already registered by " + by + ")");
    }
}

template <class Base>
std::vector<std::string> move_entries(const Registry<Base>& staged, Registry<Base>& host,
                                      std::map<std::string, std::string, std::less<>>& owner, const std::string& file) {
    for (const std::string& name : staged.names()) {
        host.add(name, staged.factory(name), staged.spec(name));
        owner[host.category() + ":" + name] = file;
    }
    return staged.names();
}

}  // namespace

fs::path installed_plugin_folder() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec || exe.empty()) return {};
    return (exe.parent_path() / RTLAB_PLUGIN_DIR_FROM_BINDIR).lexically_normal();
}

SearchPath plugin_search_path(std::vector<fs::path> plugin_dirs) {
    SearchPath path = SearchPath::from_environment(std::move(plugin_dirs), kPluginPathVariable);
    path.append(installed_plugin_folder());
    return path;
}

PluginHost::PluginHost(MaterialRegistry& materials, TextureRegistry& textures, LightRegistry& lights,
                       SearchPath search_path)
    : m_materials(materials), m_textures(textures), m_lights(lights), m_search_path(std::move(search_path)) {}

LoadedPlugin PluginHost::load_file(const fs::path& file) {
    std::error_code ec;
    const fs::path path = fs::canonical(file, ec);
    if (ec || !fs::is_regular_file(path)) throw Error("plugin " + quoted(file) + ": file not found");
    for (const LoadedPlugin& p : m_loaded) {
        if (p.file == path) return p;
    }
    const std::string name = quoted(path);

    // RTLD_NOW: a missing symbol is an error here, not a crash in the middle of a render. RTLD_LOCAL: the
    // module's symbols resolve nothing in the host or in other modules (all modules export the same two
    // names). The handle is never closed: factories and objects the module makes run its code.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw Error("plugin " + name + ": cannot load: " + dl_error());
    auto query = reinterpret_cast<RtlabPluginQueryFn>(dlsym(handle, RTLAB_PLUGIN_QUERY_SYMBOL));
    auto enrol = reinterpret_cast<RtlabPluginRegisterFn>(dlsym(handle, RTLAB_PLUGIN_REGISTER_SYMBOL));
    if (!query || !enrol)
        throw Error("plugin " + name + " is not an rtlab plugin: it does not export " +
                    (query ? RTLAB_PLUGIN_REGISTER_SYMBOL : RTLAB_PLUGIN_QUERY_SYMBOL));

    const RtlabPluginRecord* record = query();
    if (!record) throw Error("plugin " + name + ": " RTLAB_PLUGIN_QUERY_SYMBOL " returned no record");
    const RtlabPluginRecord expected = make_plugin_record("");
    const std::vector<std::string> differences = plugin_record_differences(expected, *record);
    if (!differences.empty()) {
        std::string message = "plugin " + name + " refused: it was built against another rtlab or toolchain (";
        for (std::size_t i = 0; i < differences.size(); ++i) message += (i ? "; " : "") + differences[i];
        throw Error(message + "); rebuild it against this rtlab");
    }

    // The module registers into empty registries of the host's categories; its names join the host's only
    // when none of them is taken, so a refused module changes nothing.
    MaterialRegistry materials(m_materials.category());
    TextureRegistry textures(m_textures.category());
    LightRegistry lights(m_lights.category());
    const RtlabPluginRegistries registries{RTLAB_PLUGIN_ABI_VERSION, &materials, &textures, &lights};
    std::array<char, 2048> error{};
    if (enrol(&registries, error.data(), error.size()) != 0)
        throw Error("plugin " + name + " failed to register its types: " +
                    (error[0] ? std::string(error.data()) : std::string("no reason given")));

    std::vector<std::string> clashes;
    find_clashes(materials, m_materials, m_owner, clashes);
    find_clashes(textures, m_textures, m_owner, clashes);
    find_clashes(lights, m_lights, m_owner, clashes);
    if (!clashes.empty()) {
        std::string message = "plugin " + name + " registers names that are taken: ";
        for (std::size_t i = 0; i < clashes.size(); ++i) message += (i ? ", " : "") + clashes[i];
        throw Error(message);
    }

    LoadedPlugin loaded;
    loaded.file = path;
    loaded.description = record->description ? record->description : "";
    loaded.materials = move_entries(materials, m_materials, m_owner, name);
    loaded.textures = move_entries(textures, m_textures, m_owner, name);
    loaded.lights = move_entries(lights, m_lights, m_owner, name);
    m_loaded.push_back(loaded);
    return loaded;
}

LoadedPlugin PluginHost::load_by_name(std::string_view name, std::string_view context) {
    const std::string where = context.empty() ? std::string() : std::string(context) + ": ";
    const std::string n(name);
    if (n.empty()) throw Error(where + "plugin name is empty");
    // Scene files travel between people and loading a module runs its code: a scene may only pick among
    // the modules the user installed or pointed at, never name a file of its own choosing.
    if (n.find_first_of("/\\") != std::string::npos || n == "." || n == "..")
        throw Error(where + "plugin '" + n +
                    "' is a path; a scene names plugins by name only, looked up on the plugin search path (" +
                    m_search_path.describe() + "); to load a file by its path, pass --plugin FILE");

    std::vector<std::string> candidates{n};
    if (!n.ends_with(".so")) {
        candidates.push_back(n + ".so");
        candidates.push_back("lib" + n + ".so");
    }
    // Folder by folder, so that an earlier folder (--plugin-dir) wins whatever the file's spelling.
    for (const fs::path& folder : m_search_path.folders()) {
        const SearchPath one({folder});
        for (const std::string& c : candidates) {
            if (const auto found = one.find(c)) return load_file(*found);
        }
    }
    std::string looked;
    for (std::size_t i = 0; i < candidates.size(); ++i) looked += (i ? ", '" : "'") + candidates[i] + "'";
    throw Error(where + "plugin '" + n + "' not found on the plugin search path (looked for " + looked + " in " +
                m_search_path.describe() + "); add its folder with --plugin-dir or " +
                std::string(kPluginPathVariable));
}

}  // namespace rtlab
