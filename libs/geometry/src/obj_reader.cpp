// OBJ through tinyobjloader. Polygons are read untriangulated and fanned here, so triangle order is
// exactly the one FORMATS.md specifies; vertices with normals or uvs are de-indexed into shared arrays.
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

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

// Calls f(line, line_number, offset of the line in text) for every line as tinyobjloader splits them (at \n, \r\n or a
// lone \r), cut at a NUL as its C-string parsing is, with leading blanks dropped as it drops them. The line ends and
// NULs are found with memchr: a byte loop here was 60 M of the 147 M instructions the bunny's check took.
template <class F>
void for_each_line(std::string_view text, F&& f) {
    const char* const begin = text.data();
    const char* const end = begin + text.size();
    std::size_t line_no = 0;
    const char* p = begin;
    while (p < end) {
        const auto* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
        const char* stop = nl ? nl : end;
        if (const auto* cr = static_cast<const char*>(std::memchr(p, '\r', static_cast<std::size_t>(stop - p))))
            stop = cr;
        const char* next = stop == end ? end : stop + (*stop == '\r' && stop + 1 < end && stop[1] == '\n' ? 2 : 1);
        const char* cut = p;
        const char* content_end = stop;
        if (const auto* nul = static_cast<const char*>(std::memchr(p, '\0', static_cast<std::size_t>(stop - p))))
            content_end = nul;
        while (cut < content_end && (*cut == ' ' || *cut == '\t')) ++cut;
        f(std::string_view(cut, static_cast<std::size_t>(content_end - cut)), ++line_no,
          static_cast<std::size_t>(p - begin));
        p = next;
    }
}

bool is_blank(char c) { return c == ' ' || c == '\t'; }
// Whether line is a statement of this keyword ("v", "vt", "vn", "f"): the keyword, then a blank.
bool starts_statement(std::string_view line, std::string_view keyword) {
    return line.size() > keyword.size() && line.substr(0, keyword.size()) == keyword && is_blank(line[keyword.size()]);
}

// The next blank-separated word of line from pos on (empty at its end); pos moves past it.
std::string_view next_word(std::string_view line, std::size_t& pos) {
    while (pos < line.size() && is_blank(line[pos])) ++pos;
    const std::size_t start = pos;
    while (pos < line.size() && !is_blank(line[pos])) ++pos;
    return line.substr(start, pos - start);
}

// Throws the error for one line of the file.
struct LineError {
    const std::filesystem::path& path;
    std::size_t line;
    [[noreturn]] void operator()(const std::string& what) const {
        throw Error(file_error_message(path, "line " + std::to_string(line) + ": " + what));
    }
};

// Whether w is [+-]digits or [+-]digits.digits with at most 40 characters: a number from_chars reads whole and
// finite, settled without it (the common case; 21 M instructions of from_chars on the bunny).
bool is_plain_decimal(std::string_view w) {
    if (w.size() > 40) return false;
    std::size_t i = !w.empty() && (w[0] == '-' || w[0] == '+') ? 1 : 0;
    const std::size_t int_start = i;
    while (i < w.size() && w[i] >= '0' && w[i] <= '9') ++i;
    if (i == int_start) return false;
    if (i == w.size()) return true;
    if (w[i] != '.') return false;
    const std::size_t frac_start = ++i;
    while (i < w.size() && w[i] >= '0' && w[i] <= '9') ++i;
    return i > frac_start && i == w.size();
}

// "v x y z": tinyobjloader reads "nan", "inf" and malformed numbers as 0 without a word.
void check_vertex(std::string_view line, const LineError& fail) {
    std::size_t pos = 1;
    for (std::size_t k = 0; k < 3; ++k) {
        double value = 0.0;
        std::string_view w = next_word(line, pos);
        if (is_plain_decimal(w)) continue;
        bool ok = !w.empty();
        if (ok) {
            if (w.front() == '+') w.remove_prefix(1);
            const auto [p, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
            ok = !w.empty() && ec == std::errc() && p == w.data() + w.size() && std::isfinite(value);
        }
        if (!ok) fail("vertex coordinate " + std::to_string(k + 1) + " is missing, malformed or non-finite");
    }
}

struct IndexedKind {
    const char* name;    // "vertex"
    const char* plural;  // "vertices"
};
constexpr IndexedKind kVertex{"vertex", "vertices"}, kUv{"texture coordinate", "texture coordinates"},
    kNormal{"normal", "normals"};

struct ElementCounts {
    std::int64_t positions = 0, uvs = 0, normals = 0;
};

// A positive index beyond the elements read so far: legal when the file defines the element later (tinyobjloader
// reads forward references), so it is settled against the file's totals once they are known.
struct ForwardIndex {
    std::size_t line;
    std::string text;
    const IndexedKind* kind;
    std::int64_t magnitude;  // -1: too large for an int
};

// The digits of an index, already known to be [+-]digits, as a magnitude; -1 when too large for an int.
// tinyobjloader reads them with atoi, which wraps an index too large for an int around to any other, so the
// digits are read here in 64 bits and checked against both limits.
std::int64_t index_magnitude(std::string_view text) {
    const std::string_view digits = text.substr(text.front() == '-' || text.front() == '+' ? 1 : 0);
    std::int64_t magnitude = 0;
    const auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), magnitude);
    return ec == std::errc::result_out_of_range || magnitude > std::numeric_limits<int>::max() ? -1 : magnitude;
}

[[noreturn]] void fail_out_of_range(const ForwardIndex& f, std::int64_t total, const std::filesystem::path& path) {
    LineError{path, f.line}(std::string(f.kind->name) + " index " + f.text + " out of range (" + std::to_string(total) +
                            " " + f.kind->plural + ")");
}

bool is_index(std::string_view s) {
    if (!s.empty() && (s.front() == '-' || s.front() == '+')) s.remove_prefix(1);
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Faces with fewer than 3 corners, which tinyobjloader drops without a word (FORMATS.md drops them too).
struct ShortFaces {
    std::size_t count = 0;
    std::size_t first_line = 0;
};

// The vertex and face lines tinyobjloader will read, checked first, which also gives the line number for the
// error. One pass: an index is checked against the elements read so far (negative ones count back from there);
// a positive one beyond them is kept and settled at the end against the file's totals. An error found on the way
// first settles the forward indices of earlier lines against totals counted over the rest of the file, so the
// error reported is always the first in the file, as a check against the totals up front would find it.
class LineChecker {
public:
    explicit LineChecker(const std::filesystem::path& path) : m_path(path) {}

    ShortFaces run(std::string_view text) {
        for_each_line(text, [&](std::string_view line, std::size_t line_no, std::size_t line_start) {
            try {
                check(line, line_no);
            } catch (const Error&) {
                if (!m_forward.empty()) {
                    ElementCounts total = m_so_far;
                    for_each_line(text.substr(line_start),
                                  [&](std::string_view rest, std::size_t, std::size_t) { count(total, rest); });
                    settle(total);
                }
                throw;
            }
            count(m_so_far, line);
        });
        settle(m_so_far);
        return m_short;
    }

private:
    static void count(ElementCounts& counts, std::string_view line) {
        if (line.size() < 2 || line[0] != 'v') return;
        if (is_blank(line[1]))
            ++counts.positions;
        else if (starts_statement(line, "vt"))
            ++counts.uvs;
        else if (starts_statement(line, "vn"))
            ++counts.normals;
    }

    static std::int64_t of_kind(const ElementCounts& c, const IndexedKind* kind) {
        return kind == &kVertex ? c.positions : kind == &kUv ? c.uvs : c.normals;
    }

    void settle(const ElementCounts& total) const {
        for (const ForwardIndex& f : m_forward)
            if (f.magnitude < 0 || f.magnitude > of_kind(total, f.kind))
                fail_out_of_range(f, of_kind(total, f.kind), m_path);
    }

    void check(std::string_view line, std::size_t line_no) {
        if (starts_statement(line, "v")) check_vertex(line, LineError{m_path, line_no});
        if (starts_statement(line, "f") && check_face(line, line_no) < 3 && m_short.count++ == 0)
            m_short.first_line = line_no;
    }

    void check_index(std::string_view text, const IndexedKind& kind, std::size_t line_no) {
        const LineError fail{m_path, line_no};
        const bool negative = text.front() == '-';
        const std::int64_t magnitude = index_magnitude(text);
        const std::int64_t so_far = of_kind(m_so_far, &kind);
        auto what = [&] { return std::string(kind.name) + " index " + std::string(text); };
        if (magnitude == 0) fail(what() + ": OBJ indices start at 1");
        if (negative && (magnitude < 0 || magnitude > so_far))
            fail(what() + " reaches before the first " + kind.name + " (" + std::to_string(so_far) + " " + kind.plural +
                 " so far)");
        if (!negative && (magnitude < 0 || magnitude > so_far))
            m_forward.push_back({line_no, std::string(text), &kind, magnitude});
    }

    // A corner of unsigned indices (v, v/vt, v//vn or v/vt/vn; at most 9 digits each, not 0) all within the
    // elements read so far: legal, settled without the general check below. False leaves it to that check.
    bool plain_corner_in_range(std::string_view corner) const {
        std::int64_t value[3] = {0, 0, 0};
        std::size_t digits[3] = {0, 0, 0};
        std::size_t slot = 0;
        for (const char c : corner) {
            if (c == '/') {
                if (++slot == 3) return false;
            } else if (c >= '0' && c <= '9') {
                if (++digits[slot] > 9) return false;
                value[slot] = value[slot] * 10 + (c - '0');
            } else {
                return false;
            }
        }
        // v needs its index; "v/" and "v//" are malformed, "v//vn" has no uv.
        if (digits[0] == 0 || value[0] == 0 || value[0] > m_so_far.positions) return false;
        if (slot >= 1 && (digits[1] != 0 ? value[1] == 0 || value[1] > m_so_far.uvs : slot != 2)) return false;
        if (slot == 2 && (digits[2] == 0 || value[2] == 0 || value[2] > m_so_far.normals)) return false;
        return true;
    }

    // "f c1 c2 ...", each corner v, v/vt, v//vn or v/vt/vn. Returns the number of corners.
    std::size_t check_face(std::string_view line, std::size_t line_no) {
        std::size_t pos = 1, corners = 0;
        for (std::string_view corner = next_word(line, pos); !corner.empty();
             corner = next_word(line, pos), ++corners) {
            if (plain_corner_in_range(corner)) continue;
            const auto n = 1 + static_cast<std::size_t>(std::count(corner.begin(), corner.end(), '/'));
            std::string_view slot[3];  // v, vt, vn
            for (std::size_t k = 0, start = 0; k < n && k < 3; ++k) {
                const std::size_t slash = corner.find('/', start);
                slot[k] = corner.substr(start, slash == std::string_view::npos ? slash : slash - start);
                start = slash + 1;
            }
            const bool well_formed = n <= 3 && is_index(slot[0]) &&
                                     (n < 2 || is_index(slot[1]) || (n == 3 && slot[1].empty())) &&
                                     (n < 3 || is_index(slot[2]));
            if (!well_formed)
                LineError{m_path, line_no}("face corner '" + std::string(corner) +
                                           "' is malformed (v, v/vt, v//vn or v/vt/vn with integer indices)");
            check_index(slot[0], kVertex, line_no);
            if (n >= 2 && !slot[1].empty()) check_index(slot[1], kUv, line_no);
            if (n == 3) check_index(slot[2], kNormal, line_no);
        }
        return corners;
    }

    const std::filesystem::path& m_path;
    ElementCounts m_so_far;
    std::vector<ForwardIndex> m_forward;
    ShortFaces m_short;
};

ShortFaces check_lines(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_binary_file(path);
    return LineChecker(path).run(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace

TriangleMesh load_obj(const std::filesystem::path& path, MeshLoadInfo* info) {
    auto fail = [&](const std::string& what) { throw Error(file_error_message(path, what)); };
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail("is a directory, not a file");
    if (!std::filesystem::exists(path, ec)) fail("no such file");
    if (std::filesystem::file_size(path, ec) == 0) fail("empty file");

    const ShortFaces short_faces = check_lines(path);

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
        // tinyobjloader's "Degenerated face found\n." is the short faces that the count below names by line.
        if (!line.empty() && line != "." && line != "Degenerated face found") out.warnings.push_back(line);
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
            // Fan (c0, c1, c2), (c0, c2, c3), ... in place.
            for (std::size_t c = 2; c < corners; ++c)
                mesh.triangles.push_back({vertex_of(shape.mesh.indices[offset]),
                                          vertex_of(shape.mesh.indices[offset + c - 1]),
                                          vertex_of(shape.mesh.indices[offset + c])});
            offset += corners;
        }
    }
    const std::size_t dropped = short_faces.count;
    const std::string dropped_text = std::to_string(dropped) + (dropped == 1 ? " face" : " faces") +
                                     " with fewer than 3 corners dropped (line " +
                                     std::to_string(short_faces.first_line) + (dropped == 1 ? ")" : " and later)");
    if (mesh.triangles.empty()) fail(dropped ? "no triangles: " + dropped_text : std::string("no faces"));
    if (dropped) out.warnings.push_back(dropped_text);
    return mesh;
}

}  // namespace rtlab
