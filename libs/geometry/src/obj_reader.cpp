// OBJ: rtlab's own reader of what a triangle mesh takes from the format -- v, vt, vn and f with corners v, v/vt,
// v//vn or v/vt/vn (negative indices count back from the elements read so far, positive ones may name elements
// defined later) -- in one pass that checks each line as it reads it, so that an error names the line. Other
// statements (g, o, s, usemtl, l, p, ...) are skipped; a mtllib whose file is missing is a warning. Lines,
// numbers and indices are read as tinyobjloader 2.0, which this reader replaced, read them, so meshes (and the
// images made of them) stay bit for bit what they were; tinyobjloader's own parse after our check was most of
// the time of a load. Polygons are fanned in file order, as FORMATS.md specifies; vertices with normals or uvs
// are de-indexed into shared arrays.
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/geometry/mesh_io.hpp>

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

// Calls f(line, line_number, offset of the line in text) for every line as tinyobjloader split them (at \n, \r\n or a
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
bool is_digit(char c) { return c >= '0' && c <= '9'; }
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
    while (i < w.size() && is_digit(w[i])) ++i;
    if (i == int_start) return false;
    if (i == w.size()) return true;
    if (w[i] != '.') return false;
    const std::size_t frac_start = ++i;
    while (i < w.size() && is_digit(w[i])) ++i;
    return i > frac_start && i == w.size();
}

// Whether w is a whole finite number: "nan", "inf" and malformed words are errors (tinyobjloader read them as 0
// without a word).
bool is_finite_number(std::string_view w) {
    if (is_plain_decimal(w)) return true;
    if (!w.empty() && w.front() == '+') w.remove_prefix(1);
    if (w.empty()) return false;
    double value = 0.0;
    const auto [p, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
    return ec == std::errc() && p == w.data() + w.size() && std::isfinite(value);
}

// The number at the start of [s, end) as tinyobjloader 2.0's tryParseDouble reads it: digits summed in a double,
// the fraction's digit by digit times a power of ten, an exponent through pow(5, e) and ldexp. Not correctly
// rounded as a double (from_chars is), but kept: it is how the meshes read before were read. False (value
// untouched) when there is no number there.
bool read_tinyobj_real(const char* s, const char* end, double& value) {
    if (s >= end) return false;
    double mantissa = 0.0;
    int exponent = 0;
    char sign = '+';
    const char* p = s;
    bool leading_dot = false;
    if (*p == '+' || *p == '-') {
        sign = *p++;
        leading_dot = p != end && *p == '.';
    } else if (*p == '.') {
        leading_dot = true;
    } else if (!is_digit(*p)) {
        return false;
    }
    if (!leading_dot) {
        const char* const first = p;
        for (; p != end && is_digit(*p); ++p) mantissa = mantissa * 10 + static_cast<int>(*p - '0');
        if (p == first) return false;
    }
    if (p != end && *p == '.') {
        static constexpr double kPowers[] = {1.0, 0.1, 0.01, 0.001, 0.0001, 0.00001, 0.000001, 0.0000001};
        ++p;
        for (int read = 1; p != end && is_digit(*p); ++p, ++read)
            mantissa += static_cast<int>(*p - '0') * (read < 8 ? kPowers[read] : std::pow(10.0, -read));
    }
    if (p != end && (*p == 'e' || *p == 'E')) {
        ++p;
        char exponent_sign = '+';
        if (p != end && (*p == '+' || *p == '-'))
            exponent_sign = *p++;
        else if (p == end || !is_digit(*p))
            return false;
        const char* const first = p;
        for (; p != end && is_digit(*p); ++p) {
            if (exponent > std::numeric_limits<int>::max() / 10) return false;
            // Wrapping past the int's range as tinyobjloader's int did, without its undefined behaviour.
            exponent = static_cast<int>(static_cast<unsigned>(exponent) * 10u + static_cast<unsigned>(*p - '0'));
        }
        if (p == first) return false;
        if (exponent_sign == '-') exponent = -exponent;
    }
    value =
        (sign == '+' ? 1 : -1) * (exponent != 0 ? std::ldexp(mantissa * std::pow(5.0, exponent), exponent) : mantissa);
    return true;
}

// A word's number as a float, or fallback where it has none (tinyobjloader's parseReal).
float read_real(std::string_view w, double fallback = 0.0) {
    double value = fallback;
    read_tinyobj_real(w.data(), w.data() + w.size(), value);
    return static_cast<float>(value);
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
    return !s.empty() && std::all_of(s.begin(), s.end(), is_digit);
}

// Faces with fewer than 3 corners, dropped as tinyobjloader dropped them (FORMATS.md drops them too).
struct ShortFaces {
    std::size_t count = 0;
    std::size_t first_line = 0;
};

// A face corner's indices, 0-based (negative ones resolved against the elements read before it); -1 where the
// corner has none.
struct Corner {
    std::int32_t position, uv, normal;
};

// What a file holds, as read.
struct ObjContents {
    std::vector<float> positions, uvs, normals;  // 3, 2 and 3 floats per element
    std::vector<Corner> corners;                 // of the faces kept, in file order
    std::vector<std::uint32_t> face_sizes;       // their corner counts, each at least 3
    ShortFaces short_faces;
    bool any_primitive = false;  // an f, l or p statement (l and p are skipped)
    std::vector<std::string> warnings;
};

// The reading pass. An index is checked against the elements read so far (negative ones count back from
// there); a positive one beyond them is kept and settled at the end against the file's totals. An error found on
// the way first settles the forward indices of earlier lines against totals counted over the rest of the file,
// so the error reported is always the first in the file, as a check against the totals up front would find it.
class ObjParser {
public:
    explicit ObjParser(const std::filesystem::path& path) : m_path(path) {}

    ObjContents run(std::string_view text) {
        for_each_line(text, [&](std::string_view line, std::size_t line_no, std::size_t line_start) {
            try {
                read(line, line_no);
            } catch (const Error&) {
                if (!m_forward.empty()) {
                    ElementCounts total = m_so_far;
                    for_each_line(text.substr(line_start),
                                  [&](std::string_view rest, std::size_t, std::size_t) { count(total, rest); });
                    settle(total);
                }
                throw;
            }
        });
        settle(m_so_far);
        return std::move(m_out);
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

    void read(std::string_view line, std::size_t line_no) {
        if (line.size() < 2) return;
        if (line[0] == 'v') {
            if (is_blank(line[1])) {
                read_vertex(line, line_no);
            } else if (starts_statement(line, "vt")) {
                read_reals(line, 2, m_out.uvs);
                ++m_so_far.uvs;
            } else if (starts_statement(line, "vn")) {
                read_reals(line, 3, m_out.normals);
                ++m_so_far.normals;
            }
        } else if (line[0] == 'f') {
            if (is_blank(line[1])) {
                read_face(line, line_no);
                m_out.any_primitive = true;
            }
        } else if ((line[0] == 'l' || line[0] == 'p') && is_blank(line[1])) {
            m_out.any_primitive = true;
        } else if (starts_statement(line, "mtllib")) {
            check_material_library(line, line_no);
        }
    }

    // "v x y z" (a w and colours after them are skipped).
    void read_vertex(std::string_view line, std::size_t line_no) {
        const LineError fail{m_path, line_no};
        std::size_t pos = 1;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::string_view w = next_word(line, pos);
            if (!is_finite_number(w))
                fail("vertex coordinate " + std::to_string(k + 1) + " is missing, malformed or non-finite");
            const float value = read_real(w);
            if (!std::isfinite(value))
                fail("vertex coordinate " + std::to_string(k + 1) + " is beyond a float's range");
            m_out.positions.push_back(value);
        }
        ++m_so_far.positions;
    }

    // "vt u v" or "vn x y z": n numbers, 0 for a missing or malformed one, as tinyobjloader read them (these
    // lines were never checked; a mesh with garbage normals or uvs still loads).
    static void read_reals(std::string_view line, std::size_t n, std::vector<float>& out) {
        std::size_t pos = 2;
        for (std::size_t k = 0; k < n; ++k) out.push_back(read_real(next_word(line, pos)));
    }

    // The 0-based index of a checked index word: negative ones count back from the `so_far` read before it.
    static std::int32_t resolve(std::string_view text, std::int64_t so_far) {
        const std::int64_t magnitude = index_magnitude(text);
        if (magnitude < 0) return -1;  // too large: settle() rejects it before it is used
        return static_cast<std::int32_t>(text.front() == '-' ? so_far - magnitude : magnitude - 1);
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
    // elements read so far, read into c: the common case, settled without the general reading below. False
    // leaves it to that.
    bool plain_corner_in_range(std::string_view corner, Corner& c) const {
        std::int64_t value[3] = {0, 0, 0};
        std::size_t digits[3] = {0, 0, 0};
        std::size_t slot = 0;
        for (const char ch : corner) {
            if (ch == '/') {
                if (++slot == 3) return false;
            } else if (is_digit(ch)) {
                if (++digits[slot] > 9) return false;
                value[slot] = value[slot] * 10 + (ch - '0');
            } else {
                return false;
            }
        }
        // v needs its index; "v/" and "v//" are malformed, "v//vn" has no uv.
        if (digits[0] == 0 || value[0] == 0 || value[0] > m_so_far.positions) return false;
        if (slot >= 1 && (digits[1] != 0 ? value[1] == 0 || value[1] > m_so_far.uvs : slot != 2)) return false;
        if (slot == 2 && (digits[2] == 0 || value[2] == 0 || value[2] > m_so_far.normals)) return false;
        c = {static_cast<std::int32_t>(value[0] - 1), static_cast<std::int32_t>(digits[1] != 0 ? value[1] - 1 : -1),
             static_cast<std::int32_t>(slot == 2 ? value[2] - 1 : -1)};
        return true;
    }

    // Any other corner: checked, then read.
    Corner general_corner(std::string_view corner, std::size_t line_no) {
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
        Corner c{-1, -1, -1};
        check_index(slot[0], kVertex, line_no);
        c.position = resolve(slot[0], m_so_far.positions);
        if (n >= 2 && !slot[1].empty()) {
            check_index(slot[1], kUv, line_no);
            c.uv = resolve(slot[1], m_so_far.uvs);
        }
        if (n == 3) {
            check_index(slot[2], kNormal, line_no);
            c.normal = resolve(slot[2], m_so_far.normals);
        }
        return c;
    }

    // "f c1 c2 ...": kept when it has at least 3 corners.
    void read_face(std::string_view line, std::size_t line_no) {
        const std::size_t first = m_out.corners.size();
        std::size_t pos = 1;
        for (std::string_view corner = next_word(line, pos); !corner.empty(); corner = next_word(line, pos)) {
            Corner c;
            if (!plain_corner_in_range(corner, c)) c = general_corner(corner, line_no);
            m_out.corners.push_back(c);
        }
        const std::size_t corners = m_out.corners.size() - first;
        if (corners >= 3) {
            m_out.face_sizes.push_back(static_cast<std::uint32_t>(corners));
        } else {
            m_out.corners.resize(first);
            if (m_out.short_faces.count++ == 0) m_out.short_faces.first_line = line_no;
        }
    }

    // "mtllib a.mtl ...": rtlab takes no materials from OBJ files (the scene gives the mesh its own), but a
    // library none of whose files is there is named, as tinyobjloader's warning did.
    void check_material_library(std::string_view line, std::size_t line_no) {
        std::size_t pos = 6;
        std::string names;
        for (std::string_view name = next_word(line, pos); !name.empty(); name = next_word(line, pos)) {
            std::error_code ec;
            if (std::filesystem::exists(m_path.parent_path() / name, ec)) return;
            names += (names.empty() ? "'" : ", '") + std::string(name) + "'";
        }
        m_out.warnings.push_back(
            "line " + std::to_string(line_no) + ": " +
            (names.empty() ? std::string("mtllib names no file") : "material library " + names + " not found") +
            " (OBJ materials are not read: the scene gives the mesh its material)");
    }

    const std::filesystem::path& m_path;
    ElementCounts m_so_far;
    std::vector<ForwardIndex> m_forward;
    ObjContents m_out;
};

}  // namespace

TriangleMesh load_obj(const std::filesystem::path& path, MeshLoadInfo* info) {
    auto fail = [&](const std::string& what) { throw Error(file_error_message(path, what)); };
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail("is a directory, not a file");
    if (!std::filesystem::exists(path, ec)) fail("no such file");
    if (std::filesystem::file_size(path, ec) == 0) fail("empty file");

    const std::vector<unsigned char> bytes = read_binary_file(path);
    ObjContents obj = ObjParser(path).run(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    MeshLoadInfo local;
    MeshLoadInfo& out = info ? *info : local;
    out.format = "obj";
    out.warnings.insert(out.warnings.end(), obj.warnings.begin(), obj.warnings.end());

    const std::size_t position_count = obj.positions.size() / 3;
    const std::size_t normal_count = obj.normals.size() / 3;
    const std::size_t uv_count = obj.uvs.size() / 2;
    if (position_count == 0 && !obj.any_primitive) fail("no vertices or faces found: not an OBJ file?");

    // Normals and uvs are kept only when every face corner has one (the parser checked every index).
    bool all_normals = normal_count > 0, all_uvs = uv_count > 0;
    for (const Corner& c : obj.corners) {
        if (c.normal < 0) all_normals = false;
        if (c.uv < 0) all_uvs = false;
    }

    TriangleMesh mesh;
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> corner_vertex;
    const bool deindex = all_normals || all_uvs;
    const std::vector<float>& p = obj.positions;
    if (!deindex) {
        mesh.positions.reserve(position_count);
        for (std::size_t i = 0; i < position_count; ++i)
            mesh.positions.emplace_back(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    }
    auto vertex_of = [&](const Corner& c) -> std::uint32_t {
        if (!deindex) return static_cast<std::uint32_t>(c.position);
        const CornerKey key{c.position, all_normals ? c.normal : -1, all_uvs ? c.uv : -1};
        auto [it, inserted] = corner_vertex.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
        if (inserted) {
            const auto v = static_cast<std::size_t>(key.position);
            mesh.positions.emplace_back(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
            if (all_normals) {
                const auto n = static_cast<std::size_t>(key.normal);
                mesh.normals.emplace_back(obj.normals[3 * n], obj.normals[3 * n + 1], obj.normals[3 * n + 2]);
            }
            if (all_uvs) {
                const auto t = static_cast<std::size_t>(key.uv);
                mesh.uvs.emplace_back(obj.uvs[2 * t], obj.uvs[2 * t + 1]);
            }
        }
        return it->second;
    };

    std::size_t offset = 0;
    mesh.triangles.reserve(obj.corners.size() - 2 * obj.face_sizes.size());
    for (const std::uint32_t corners : obj.face_sizes) {
        // Fan (c0, c1, c2), (c0, c2, c3), ... in place.
        for (std::size_t c = 2; c < corners; ++c)
            mesh.triangles.push_back({vertex_of(obj.corners[offset]), vertex_of(obj.corners[offset + c - 1]),
                                      vertex_of(obj.corners[offset + c])});
        offset += corners;
    }
    const std::size_t dropped = obj.short_faces.count;
    const std::string dropped_text = std::to_string(dropped) + (dropped == 1 ? " face" : " faces") +
                                     " with fewer than 3 corners dropped (line " +
                                     std::to_string(obj.short_faces.first_line) + (dropped == 1 ? ")" : " and later)");
    if (mesh.triangles.empty()) fail(dropped ? "no triangles: " + dropped_text : std::string("no faces"));
    if (dropped) out.warnings.push_back(dropped_text);
    return mesh;
}

}  // namespace rtlab
