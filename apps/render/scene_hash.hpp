#pragma once
// The scene hash of a share file (rtlab/render/sample_share.hpp): what makes shares of different scenes or
// settings refuse to merge.
#include <rtlab/scene/scene_loader.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace rtlab::app {

/// FNV-1a (64-bit) over: the scene file's bytes; the logical name and the bytes of every file it named (meshes,
/// textures: the loader's asset list), so that a mesh edited between two shares is caught; the plugin modules' file
/// names; and what the command line can change in the picture beyond the share header (integrator, depth,
/// anti-aliasing pattern). Contents, not paths: the shares of one frame may be rendered on machines whose folders
/// differ. Throws rtlab::Error naming a file it cannot read.
std::uint64_t scene_hash(const std::filesystem::path& scene_file, const LoadedScene& scene,
                         const std::vector<std::filesystem::path>& plugins);

}  // namespace rtlab::app
