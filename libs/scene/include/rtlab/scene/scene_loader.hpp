#pragma once
/// \brief JSON scene files: one document in, a RenderJob and its output settings out.
#include <rtlab/core/data_path.hpp>
#include <rtlab/geometry/transform.hpp>
#include <rtlab/render/image_limits.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/scene/scene_registries.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// The scene format version this loader reads.
inline constexpr int kSceneFormatVersion = 1;

/// \brief Values that replace the scene file's (the command line's --width, --spp, ...). An override is
/// checked like the file's value and its errors are reported with the file's.
struct SceneOverrides {
    std::optional<int> width, height;  ///< one alone keeps the file's aspect ratio
    std::optional<int> spp;
    std::optional<std::string> aa;  ///< none | grid | random | jittered | adaptive
    std::optional<int> threads;
    std::optional<std::string> tonemap;  ///< a tone operator name or "none"
    std::optional<std::uint64_t> seed;
    std::optional<int> max_depth;           ///< the integrator's recursion depth
    std::optional<std::string> integrator;  ///< whitted | direct | path | photon | sppm
};

/// \brief How to load a scene.
struct SceneLoadOptions {
    /// Where the files a scene names are found after the scene's own folder (rtlab/core/data_path.hpp: a
    /// program passes its --data-dir, environment and checkout through DataPath::from_environment). When
    /// absent: `data_dirs`, then (use_environment) RTLAB_DATA_PATH, RTLAB_SHARED_DIR and the data packages.
    std::optional<DataPath> data_path;
    std::vector<std::filesystem::path> data_dirs;
    bool use_environment = true;
    /// Called with each name of the scene's "plugins" list before any type is looked up; it loads the
    /// module so that its types are in `registries`. Absent: a scene naming plugins is an error.
    std::function<void(const std::string&)> plugin_loader;
    /// The registries types are looked up in; nullptr: the built-ins.
    SceneRegistries* registries = nullptr;
    SceneOverrides overrides;
};

/// \brief A loaded scene: the render job and what to do with the image.
struct LoadedScene {
    RenderJob job;
    /// render.output, relative to the scene file's folder; empty when the file names none.
    std::filesystem::path output;
    std::string tone_name = "none";
    std::shared_ptr<const ToneOperator> tone;  ///< nullptr for "none" (clamp)
    std::vector<std::string> plugins;          ///< the names the file asked for, in order
    std::vector<std::string> warnings;         ///< non-fatal problems (a mesh's missing .mtl, say)
    std::vector<AssetUse> assets;              ///< the files the scene named, where each was found (describe_sources)
};

/// Loads a scene file. All problems of the file are collected and thrown together as one rtlab::Error,
/// one per line: "FILE:LINE:COLUMN: /json/pointer: what was wrong and what was expected" (syntax errors
/// give the position of the error). Unknown keys, duplicate keys, unknown types and names that refer to
/// nothing are errors. Files the scene names are found relative to its folder (a bare "scene.json" is in the
/// current folder), then on the data path (SceneLoadOptions::data_path).
LoadedScene load_scene(const std::filesystem::path& file, const SceneLoadOptions& options = {});

/// The same for a document already in memory; `file` names it in messages and its folder is where relative
/// file names are looked up first (empty: the current folder).
LoadedScene parse_scene(std::string_view text, const std::filesystem::path& file, const SceneLoadOptions& options = {});

}  // namespace rtlab
