#pragma once
/// \brief Loading triangle meshes from PLY and OBJ (own readers).
#include <rtlab/geometry/triangle_mesh.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace rtlab {

/// \brief What a loader reports besides the mesh.
struct MeshLoadInfo {
    std::string format;  ///< "ply ascii", "ply binary_little_endian", "obj", ...
    /// Non-fatal problems: a missing .mtl; faces with fewer than 3 corners, dropped (their count and the first,
    /// by line in OBJ and ASCII PLY, by element index in PLY). A file left with no triangle is an error.
    std::vector<std::string> warnings;
};

/// Loads by extension (.ply or .obj, any case). Bad input throws rtlab::Error naming the file, the
/// line or element and the problem; nothing partial is returned.
TriangleMesh load_mesh(const std::filesystem::path& path, MeshLoadInfo* info = nullptr);
TriangleMesh load_ply(const std::filesystem::path& path, MeshLoadInfo* info = nullptr);
TriangleMesh load_obj(const std::filesystem::path& path, MeshLoadInfo* info = nullptr);

}  // namespace rtlab
