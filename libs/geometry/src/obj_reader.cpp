// OBJ through tinyobjloader. Polygons are read untriangulated and fanned here, so triangle order is
// exactly the one FORMATS.md specifies; vertices with normals or uvs are de-indexed into shared arrays.
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>
#include <string>
#include <unordered_map>

namespace rtlab {

namespace {

struct CornerKey {
    int position, normal, uv;
    bool operator==(const CornerKey&) const = default;
};
struct CornerKeyHash {
    std::size_t operator()(const CornerKey& k) const {
        std::size_t h = static_cast<std::size_t>(k.position) * 0x9E3779B97F4A7C15ull;
        h ^= static_cast<std::size_t>(k.normal) + 0x9E3779B9u + (h << 6) + (h >> 2);
        h ^= static_cast<std::size_t>(k.uv) + 0x9E3779B9u + (h << 6) + (h >> 2);
        return h;
    }
};

// tinyobjloader reads "nan", "inf" and malformed numbers in vertex lines as 0 without a word, so vertex
// lines are checked here first, which also gives the line number for the error.
void check_vertex_lines(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_binary_file(path);
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    std::size_t line_no = 0, pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        ++line_no;
        pos = end + 1;
        if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
        std::size_t i = 1;
        for (int k = 0; k < 3; ++k) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
            std::size_t stop = i;
            while (stop < line.size() && line[stop] != ' ' && line[stop] != '\t' && line[stop] != '\r') ++stop;
            double value = 0.0;
            const char* first = line.data() + i;
            if (i < stop && *first == '+') ++first;
            const auto [p, ec] = std::from_chars(first, line.data() + stop, value);
            if (i == stop || ec != std::errc() || p != line.data() + stop || !std::isfinite(value))
                throw Error(file_error_message(path, "line " + std::to_string(line_no) + ": vertex coordinate " +
                                                         std::to_string(k + 1) + " is missing, malformed or non-finite"));
            i = stop;
        }
    }
}

}  // namespace

TriangleMesh load_obj(const std::filesystem::path& path, MeshLoadInfo* info) {
    auto fail = [&](const std::string& what) { throw Error(file_error_message(path, what)); };
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail("is a directory, not a file");
    if (!std::filesystem::exists(path, ec)) fail("no such file");
    if (std::filesystem::file_size(path, ec) == 0) fail("empty file");

    check_vertex_lines(path);

    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    config.vertex_color = false;
    config.mtl_search_path = path.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path.string(), config)) {
        std::string err = reader.Error();
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        fail(err.empty() ? std::string("cannot parse OBJ") : err);
    }
    MeshLoadInfo local;
    MeshLoadInfo& out = info ? *info : local;
    out.format = "obj";
    std::string warning = reader.Warning();
    std::size_t start = 0;
    while (start < warning.size()) {
        const std::size_t stop = warning.find('\n', start);
        const std::string line = warning.substr(start, stop == std::string::npos ? std::string::npos : stop - start);
        if (!line.empty()) out.warnings.push_back(line);
        if (stop == std::string::npos) break;
        start = stop + 1;
    }

    const auto& attrib = reader.GetAttrib();
    const auto& shapes = reader.GetShapes();
    const std::size_t position_count = attrib.vertices.size() / 3;
    const std::size_t normal_count = attrib.normals.size() / 3;
    const std::size_t uv_count = attrib.texcoords.size() / 2;
    if (position_count == 0 && shapes.empty()) fail("no vertices or faces found: not an OBJ file?");
    for (std::size_t i = 0; i < attrib.vertices.size(); ++i)
        if (!std::isfinite(attrib.vertices[i])) fail("vertex " + std::to_string(i / 3 + 1) + ": non-finite coordinate");

    // Normals and uvs are kept only when every face corner has one.
    bool all_normals = normal_count > 0, all_uvs = uv_count > 0;
    for (const auto& shape : shapes)
        for (const auto& idx : shape.mesh.indices) {
            if (idx.vertex_index < 0 || static_cast<std::size_t>(idx.vertex_index) >= position_count)
                fail("face in '" + shape.name + "': vertex index " + std::to_string(idx.vertex_index + 1) +
                     " out of range (" + std::to_string(position_count) + " vertices)");
            if (idx.normal_index < 0 || static_cast<std::size_t>(idx.normal_index) >= normal_count) all_normals = false;
            if (idx.texcoord_index < 0 || static_cast<std::size_t>(idx.texcoord_index) >= uv_count) all_uvs = false;
        }

    TriangleMesh mesh;
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> corner_vertex;
    const bool deindex = all_normals || all_uvs;
    if (!deindex) {
        mesh.positions.reserve(position_count);
        for (std::size_t i = 0; i < position_count; ++i)
            mesh.positions.emplace_back(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
    }
    auto vertex_of = [&](const tinyobj::index_t& idx) -> std::uint32_t {
        if (!deindex) return static_cast<std::uint32_t>(idx.vertex_index);
        const CornerKey key{idx.vertex_index, all_normals ? idx.normal_index : -1, all_uvs ? idx.texcoord_index : -1};
        auto [it, inserted] = corner_vertex.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
        if (inserted) {
            const auto p = static_cast<std::size_t>(key.position);
            mesh.positions.emplace_back(attrib.vertices[3 * p], attrib.vertices[3 * p + 1], attrib.vertices[3 * p + 2]);
            if (all_normals) {
                const auto n = static_cast<std::size_t>(key.normal);
                mesh.normals.emplace_back(attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]);
            }
            if (all_uvs) {
                const auto t = static_cast<std::size_t>(key.uv);
                mesh.uvs.emplace_back(attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]);
            }
        }
        return it->second;
    };

    for (const auto& shape : shapes) {
        std::size_t offset = 0;
        for (const auto corners : shape.mesh.num_face_vertices) {
            // Fan (c0, c1, c2), (c0, c2, c3), ... in place; faces with fewer than 3 corners are dropped.
            for (std::size_t c = 2; c < corners; ++c)
                mesh.triangles.push_back({vertex_of(shape.mesh.indices[offset]),
                                          vertex_of(shape.mesh.indices[offset + c - 1]),
                                          vertex_of(shape.mesh.indices[offset + c])});
            offset += corners;
        }
    }
    return mesh;
}

}  // namespace rtlab
