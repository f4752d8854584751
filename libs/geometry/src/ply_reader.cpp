// PLY reader: ascii, binary_little_endian and binary_big_endian; vertex properties in any order and of any
// numeric type; faces as lists of any length (fanned); unknown elements and properties skipped. Bounded:
// the header's counts are checked against the bytes that follow before anything is allocated.
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/geometry/mesh_io.hpp>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

namespace {

enum class PlyType { i8, u8, i16, u16, i32, u32, f32, f64 };
enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

std::size_t type_size(PlyType t) {
    switch (t) {
        case PlyType::i8:
        case PlyType::u8:
            return 1;
        case PlyType::i16:
        case PlyType::u16:
            return 2;
        case PlyType::i32:
        case PlyType::u32:
        case PlyType::f32:
            return 4;
        case PlyType::f64:
            return 8;
    }
    return 0;
}

std::optional<PlyType> parse_type(std::string_view s) {
    if (s == "char" || s == "int8") return PlyType::i8;
    if (s == "uchar" || s == "uint8") return PlyType::u8;
    if (s == "short" || s == "int16") return PlyType::i16;
    if (s == "ushort" || s == "uint16") return PlyType::u16;
    if (s == "int" || s == "int32") return PlyType::i32;
    if (s == "uint" || s == "uint32") return PlyType::u32;
    if (s == "float" || s == "float32") return PlyType::f32;
    if (s == "double" || s == "float64") return PlyType::f64;
    return std::nullopt;
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::f32;
    bool is_list = false;
    PlyType count_type = PlyType::u8;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

class PlyReader {
public:
    PlyReader(const std::filesystem::path& path, std::vector<unsigned char> bytes)
        : m_path(path), m_bytes(std::move(bytes)) {}

    TriangleMesh read(MeshLoadInfo* info) {
        if (m_bytes.empty()) fail("empty file");
        parse_header();
        check_sizes();
        TriangleMesh mesh;
        for (std::size_t e = 0; e < m_elements.size(); ++e) read_element(e, mesh);
        if (m_vertex_element < 0) fail("no 'vertex' element");
        // As the OBJ reader reports them: a count and the first, a warning, or the error when nothing is left.
        const std::uint64_t dropped = m_short_faces;
        const std::string dropped_text = std::to_string(dropped) + (dropped == 1 ? " face" : " faces") +
                                         " with fewer than 3 corners dropped (" + m_first_short_face +
                                         (dropped == 1 ? ")" : " and later)");
        if (mesh.triangles.empty()) fail(dropped ? "no triangles: " + dropped_text : std::string("no faces"));
        if (dropped && info) info->warnings.push_back(dropped_text);
        if (info) {
            info->format = m_format == PlyFormat::ascii                  ? "ply ascii"
                           : m_format == PlyFormat::binary_little_endian ? "ply binary_little_endian"
                                                                         : "ply binary_big_endian";
        }
        return mesh;
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw Error(file_error_message(m_path, what)); }
    [[noreturn]] void fail_line(std::size_t line, const std::string& what) const {
        fail("line " + std::to_string(line) + ": " + what);
    }

    // --- header ---------------------------------------------------------------------------------------
    std::string_view next_header_line(std::size_t& line_no) {
        const auto* begin = reinterpret_cast<const char*>(m_bytes.data());
        const std::size_t end = m_bytes.size();
        if (m_pos >= end) fail("header ends before 'end_header'");
        std::size_t stop = m_pos;
        while (stop < end && m_bytes[stop] != '\n') {
            if (stop - m_pos > 4096) fail_line(line_no + 1, "header line longer than 4096 bytes");
            ++stop;
        }
        std::string_view line(begin + m_pos, stop - m_pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        m_pos = stop < end ? stop + 1 : end;
        ++line_no;
        return line;
    }

    void parse_header() {
        std::size_t line_no = 0;
        if (next_header_line(line_no) != "ply") fail("not a PLY file (first line is not 'ply')");
        bool have_format = false;
        for (;;) {
            const std::string_view line = next_header_line(line_no);
            const auto words = split_words(line);
            if (words.empty()) continue;
            const std::string_view key = words[0];
            if (key == "end_header") break;
            if (key == "comment" || key == "obj_info") continue;
            if (key == "format") {
                if (words.size() != 3) fail_line(line_no, "malformed format line");
                if (words[1] == "ascii")
                    m_format = PlyFormat::ascii;
                else if (words[1] == "binary_little_endian")
                    m_format = PlyFormat::binary_little_endian;
                else if (words[1] == "binary_big_endian")
                    m_format = PlyFormat::binary_big_endian;
                else
                    fail_line(line_no, "unknown format '" + std::string(words[1]) + "'");
                have_format = true;
            } else if (key == "element") {
                if (words.size() != 3) fail_line(line_no, "malformed element line");
                PlyElement el;
                el.name = std::string(words[1]);
                const auto [p, ec] = std::from_chars(words[2].data(), words[2].data() + words[2].size(), el.count);
                if (ec != std::errc() || p != words[2].data() + words[2].size())
                    fail_line(line_no,
                              "element '" + el.name + "' has an invalid count '" + std::string(words[2]) + "'");
                if (el.name == "vertex") m_vertex_element = static_cast<int>(m_elements.size());
                if (el.name == "face") m_face_element = static_cast<int>(m_elements.size());
                m_elements.push_back(std::move(el));
            } else if (key == "property") {
                if (m_elements.empty()) fail_line(line_no, "property before any element");
                PlyProperty prop;
                if (words.size() >= 2 && words[1] == "list") {
                    if (words.size() != 5) fail_line(line_no, "malformed list property");
                    const auto count_type = parse_type(words[2]);
                    const auto item_type = parse_type(words[3]);
                    if (!count_type || !item_type) fail_line(line_no, "unknown property type");
                    if (*count_type == PlyType::f32 || *count_type == PlyType::f64)
                        fail_line(line_no, "list count type must be an integer type");
                    prop = {std::string(words[4]), *item_type, true, *count_type};
                } else {
                    if (words.size() != 3) fail_line(line_no, "malformed property line");
                    const auto type = parse_type(words[1]);
                    if (!type) fail_line(line_no, "unknown property type '" + std::string(words[1]) + "'");
                    prop = {std::string(words[2]), *type, false, PlyType::u8};
                }
                m_elements.back().properties.push_back(std::move(prop));
            } else {
                fail_line(line_no, "unknown header keyword '" + std::string(key) + "'");
            }
        }
        if (!have_format) fail("header has no format line");
        m_data_line = line_no + 1;
    }

    // The smallest number of bytes each element's data can take: enough to reject a header that claims
    // far more elements than the file holds, before reserving memory for them.
    void check_sizes() const {
        const std::size_t available = m_bytes.size() - m_pos;
        long double needed = 0.0L;
        for (const auto& el : m_elements) {
            long double per = 0.0L;
            for (const auto& p : el.properties)
                per += m_format == PlyFormat::ascii
                           ? 2.0L
                           : static_cast<long double>(type_size(p.is_list ? p.count_type : p.type));
            const long double total = per * static_cast<long double>(el.count);
            needed += total;
            if (needed > static_cast<long double>(available) + 1.0L)
                fail("header claims " + std::to_string(el.count) + " '" + el.name + "' elements, more than the " +
                     std::to_string(available) + " bytes of data can hold");
        }
        if (m_vertex_element >= 0 && m_elements[m_vertex_element].count > 0xFFFFFFFEull)
            fail("too many vertices for 32-bit indices");
    }

    // --- values ----------------------------------------------------------------------------------------
    double read_value(PlyType type, const PlyElement& el, std::uint64_t index) {
        if (m_format == PlyFormat::ascii)
            return read_ascii_value(el, index, type != PlyType::f32 && type != PlyType::f64);
        const std::size_t size = type_size(type);
        if (m_bytes.size() - m_pos < size)
            fail("truncated data in element '" + el.name + "' #" + std::to_string(index));
        unsigned char raw[8];
        std::memcpy(raw, m_bytes.data() + m_pos, size);
        m_pos += size;
        const bool file_little = m_format == PlyFormat::binary_little_endian;
        if (file_little != (std::endian::native == std::endian::little))
            for (std::size_t i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
        switch (type) {
            case PlyType::i8: {
                std::int8_t v;
                std::memcpy(&v, raw, 1);
                return v;
            }
            case PlyType::u8:
                return raw[0];
            case PlyType::i16: {
                std::int16_t v;
                std::memcpy(&v, raw, 2);
                return v;
            }
            case PlyType::u16: {
                std::uint16_t v;
                std::memcpy(&v, raw, 2);
                return v;
            }
            case PlyType::i32: {
                std::int32_t v;
                std::memcpy(&v, raw, 4);
                return v;
            }
            case PlyType::u32: {
                std::uint32_t v;
                std::memcpy(&v, raw, 4);
                return v;
            }
            case PlyType::f32: {
                float v;
                std::memcpy(&v, raw, 4);
                return v;
            }
            case PlyType::f64: {
                double v;
                std::memcpy(&v, raw, 8);
                return v;
            }
        }
        return 0.0;
    }

    // Blanks between ASCII values; a table, as this runs for every byte of the data (about 20 instructions a byte
    // with four comparisons per byte before, for the 7.3 MB dragon).
    static bool is_separator(char c) {
        static constexpr auto kTable = [] {
            std::array<bool, 256> t{};
            t[' '] = t['\t'] = t['\r'] = t['\n'] = true;
            return t;
        }();
        return kTable[static_cast<unsigned char>(c)];
    }

    double read_ascii_value(const PlyElement& el, std::uint64_t index, bool integer) {
        const auto* text = reinterpret_cast<const char*>(m_bytes.data());
        const std::size_t end = m_bytes.size();
        while (m_pos < end && is_separator(text[m_pos])) {
            if (text[m_pos] == '\n') ++m_data_line;
            ++m_pos;
        }
        if (m_pos >= end)
            fail("truncated data in element '" + el.name + "' #" + std::to_string(index) + " (end of file)");
        std::size_t stop = m_pos;
        while (stop < end && !is_separator(text[stop])) ++stop;
        const char* first = text + m_pos;
        if (*first == '+') ++first;  // from_chars does not accept a leading '+'
        // Indices and list lengths are integers: read as such they cost a third of a double's parse. Anything
        // else (1.5, 2e0, too many digits) takes the double path, which decides as before.
        if (integer) {
            std::int64_t whole = 0;
            const auto [p, ec] = std::from_chars(first, text + stop, whole);
            if (ec == std::errc() && p == text + stop && whole > -(std::int64_t{1} << 53) &&
                whole < (std::int64_t{1} << 53)) {
                m_pos = stop;
                return static_cast<double>(whole);
            }
        }
        double value = 0.0;
        const auto [p, ec] = std::from_chars(first, text + stop, value);
        if (ec != std::errc() || p != text + stop)
            fail_line(m_data_line, "element '" + el.name + "' #" + std::to_string(index) + ": bad number '" +
                                       std::string(text + m_pos, std::min<std::size_t>(stop - m_pos, 32)) + "'");
        m_pos = stop;
        return value;
    }

    std::string where(const PlyElement& el, std::uint64_t index) const {
        std::string s = "element '" + el.name + "' #" + std::to_string(index);
        if (m_format == PlyFormat::ascii) s = "line " + std::to_string(m_data_line) + ": " + s;
        return s;
    }

    void read_element(std::size_t e, TriangleMesh& mesh) {
        const PlyElement& el = m_elements[e];
        if (static_cast<int>(e) == m_vertex_element) return read_vertices(el, mesh);
        if (static_cast<int>(e) == m_face_element) return read_faces(el, mesh);
        for (std::uint64_t i = 0; i < el.count; ++i) skip_element(el, i);
    }

    void skip_element(const PlyElement& el, std::uint64_t i) {
        for (const auto& p : el.properties) {
            if (!p.is_list) {
                read_value(p.type, el, i);
                continue;
            }
            const std::uint64_t n = list_count(p, el, i);
            for (std::uint64_t k = 0; k < n; ++k) read_value(p.type, el, i);
        }
    }

    std::uint64_t list_count(const PlyProperty& p, const PlyElement& el, std::uint64_t i) {
        const double n = read_value(p.count_type, el, i);
        if (!(n >= 0.0) || n != std::floor(n) || n > 4294967295.0)
            fail(where(el, i) + ": invalid list length " + std::to_string(n));
        return static_cast<std::uint64_t>(n);
    }

    void read_vertices(const PlyElement& el, TriangleMesh& mesh) {
        int xyz[3] = {-1, -1, -1}, nxyz[3] = {-1, -1, -1}, uv[2] = {-1, -1};
        for (std::size_t k = 0; k < el.properties.size(); ++k) {
            const std::string& n = el.properties[k].name;
            const int idx = static_cast<int>(k);
            if (el.properties[k].is_list) continue;
            if (n == "x")
                xyz[0] = idx;
            else if (n == "y")
                xyz[1] = idx;
            else if (n == "z")
                xyz[2] = idx;
            else if (n == "nx")
                nxyz[0] = idx;
            else if (n == "ny")
                nxyz[1] = idx;
            else if (n == "nz")
                nxyz[2] = idx;
            else if (n == "u" || n == "s" || n == "texture_u" || n == "texture_s")
                uv[0] = idx;
            else if (n == "v" || n == "t" || n == "texture_v" || n == "texture_t")
                uv[1] = idx;
        }
        if (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0) fail("'vertex' element lacks x, y or z");
        const bool normals = nxyz[0] >= 0 && nxyz[1] >= 0 && nxyz[2] >= 0;
        const bool uvs = uv[0] >= 0 && uv[1] >= 0;
        mesh.positions.reserve(el.count);
        if (normals) mesh.normals.reserve(el.count);
        if (uvs) mesh.uvs.reserve(el.count);
        std::vector<double> values(el.properties.size());
        for (std::uint64_t i = 0; i < el.count; ++i) {
            for (std::size_t k = 0; k < el.properties.size(); ++k) {
                const auto& p = el.properties[k];
                if (!p.is_list) {
                    values[k] = read_value(p.type, el, i);
                    continue;
                }
                const std::uint64_t n = list_count(p, el, i);
                for (std::uint64_t j = 0; j < n; ++j) read_value(p.type, el, i);
            }
            const Point3 pos(static_cast<float>(values[xyz[0]]), static_cast<float>(values[xyz[1]]),
                             static_cast<float>(values[xyz[2]]));
            if (!is_finite(pos)) fail(where(el, i) + ": non-finite vertex coordinate");
            mesh.positions.push_back(pos);
            if (normals)
                mesh.normals.emplace_back(static_cast<float>(values[nxyz[0]]), static_cast<float>(values[nxyz[1]]),
                                          static_cast<float>(values[nxyz[2]]));
            if (uvs) mesh.uvs.emplace_back(static_cast<float>(values[uv[0]]), static_cast<float>(values[uv[1]]));
        }
    }

    void read_faces(const PlyElement& el, TriangleMesh& mesh) {
        int indices = -1;
        for (std::size_t k = 0; k < el.properties.size(); ++k) {
            const auto& p = el.properties[k];
            if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) indices = static_cast<int>(k);
        }
        if (indices < 0) fail("'face' element has no 'vertex_indices' list");
        if (m_vertex_element < 0 || m_vertex_element > m_face_element)
            fail("'face' element before the 'vertex' element");
        const auto vertex_count = static_cast<std::uint64_t>(mesh.positions.size());
        mesh.triangles.reserve(el.count);
        std::vector<std::uint32_t> corners;
        for (std::uint64_t i = 0; i < el.count; ++i) {
            for (std::size_t k = 0; k < el.properties.size(); ++k) {
                const auto& p = el.properties[k];
                if (!p.is_list) {
                    read_value(p.type, el, i);
                    continue;
                }
                const std::uint64_t n = list_count(p, el, i);
                if (static_cast<int>(k) != indices) {
                    for (std::uint64_t j = 0; j < n; ++j) read_value(p.type, el, i);
                    continue;
                }
                corners.clear();
                for (std::uint64_t j = 0; j < n; ++j) {
                    const double v = read_value(p.type, el, i);
                    if (!(v >= 0.0) || v != std::floor(v) || v >= static_cast<double>(vertex_count))
                        fail(where(el, i) + ": vertex index " + std::to_string(static_cast<long long>(v)) +
                             " out of range (" + std::to_string(vertex_count) + " vertices)");
                    corners.push_back(static_cast<std::uint32_t>(v));
                }
                // Fan (c0, c1, c2), (c0, c2, c3), ... in place; faces with fewer than 3 corners are dropped.
                if (corners.size() < 3 && m_short_faces++ == 0) m_first_short_face = where(el, i);
                for (std::size_t c = 2; c < corners.size(); ++c)
                    mesh.triangles.push_back({corners[0], corners[c - 1], corners[c]});
            }
        }
    }

    const std::filesystem::path& m_path;
    std::vector<unsigned char> m_bytes;
    std::size_t m_pos = 0;
    std::size_t m_data_line = 0;
    PlyFormat m_format = PlyFormat::ascii;
    std::vector<PlyElement> m_elements;
    int m_vertex_element = -1;
    int m_face_element = -1;
    std::uint64_t m_short_faces = 0;  ///< faces with fewer than 3 corners, dropped
    std::string m_first_short_face;   ///< where() of the first
};

}  // namespace

TriangleMesh load_ply(const std::filesystem::path& path, MeshLoadInfo* info) {
    PlyReader reader(path, read_binary_file(path));
    return reader.read(info);
}

}  // namespace rtlab
