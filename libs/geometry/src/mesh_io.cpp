#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <cctype>
#include <string>

namespace rtlab {

TriangleMesh load_mesh(const std::filesystem::path& path, MeshLoadInfo* info) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".ply") return load_ply(path, info);
    if (ext == ".obj") return load_obj(path, info);
    throw Error(file_error_message(path, "unknown mesh format '" + ext + "' (use .ply or .obj)"));
}

}  // namespace rtlab
