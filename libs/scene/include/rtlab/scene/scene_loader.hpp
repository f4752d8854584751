#pragma once
/// \brief JSON scene files: one document in, a RenderJob and its output settings out.
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
    std::optional<int> max_depth;  ///< the integrator's recursion depth
};

/// \brief How to load a scene.
struct SceneLoadOptions {
    /// Folders searched for the files a scene names, after the scene's own folder (--data-dir).
    std::vector<std::filesystem::path> data_dirs;
    /// Also search the folders of the RTLAB_DATA_PATH environment variable, after data_dirs.
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
};

/// Loads a scene file. All problems of the file are collected and thrown together as one rtlab::Error,
/// one per line: "FILE:LINE:COLUMN: /json/pointer: what was wrong and what was expected" (syntax errors
/// give the position of the error). Unknown keys, duplicate keys, unknown types and names that refer to
/// nothing are errors. Files the scene names are found relative to its folder, then in
/// options.data_dirs, then on RTLAB_DATA_PATH.
LoadedScene load_scene(const std::filesystem::path& file, const SceneLoadOptions& options = {});

/// The same for a document already in memory; `file` names it in messages and its folder is where relative
/// file names are looked up first (empty: the current folder).
LoadedScene parse_scene(std::string_view text, const std::filesystem::path& file, const SceneLoadOptions& options = {});

}  // namespace rtlab
