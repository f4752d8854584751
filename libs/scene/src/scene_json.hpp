#pragma once
// Private to the scene loader: a JSON document that remembers where each value starts, and the list of
// errors a scene file collects before they are thrown together.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab::scene_detail {

// Ordered, so that errors come in the order of the file.
using Json = nlohmann::ordered_json;

// "/materials/3/ks" for the path {materials, 3, ks}, with '~' and '/' escaped as RFC 6901 says.
std::string pointer_append(const std::string& pointer, std::string_view token);
std::string pointer_append(const std::string& pointer, std::size_t index);

// Errors of one file, each "FILE:LINE:COLUMN: POINTER: message" (no position when none is known).
class Diagnostics {
public:
    explicit Diagnostics(std::string file) : m_file(std::move(file)) {}

    // The text, for line numbers, and where the value at each pointer (for an object member: its key)
    // starts; both set by parse_json.
    void set_text(std::string_view text);
    void set_offsets(std::map<std::string, std::size_t> offsets) { m_offsets = std::move(offsets); }
    void error(const std::string& pointer, const std::string& message);
    // An error at a known byte offset, for syntax errors.
    void error_at(std::size_t offset, const std::string& message);

    bool empty() const { return m_lines.empty(); }
    std::size_t count() const { return m_lines.size(); }
    // Every error, one per line; at most kMaxLines, then how many more there were.
    std::string message() const;
    // "LINE:COLUMN" of the value at pointer, or "" when unknown.
    std::string position(const std::string& pointer) const;
    const std::string& file() const { return m_file; }
    // "LINE:COLUMN" of a byte offset.
    std::string location(std::size_t offset) const;

private:
    static constexpr std::size_t kMaxLines = 100;
    std::string m_file;
    std::map<std::string, std::size_t> m_offsets;
    std::vector<std::size_t> m_line_starts{0};
    std::vector<std::pair<std::size_t, std::string>> m_lines;  // offset (SIZE_MAX: none), text
};

// Limits that keep loading linear in the file's size whatever the file holds.
inline constexpr std::size_t kMaxNesting = 64;
inline constexpr std::size_t kMaxKeyLength = 256;

// Parses a JSON document with comments. Syntax errors and duplicate keys go to `diag`; nullopt when the
// text is not JSON at all (a syntax error).
std::optional<Json> parse_json(std::string_view text, Diagnostics& diag);

// "the string \"abc\"", "the number 3", "an object", "a list of 2 values", "null", "true": what was found.
std::string describe(const Json& value);

}  // namespace rtlab::scene_detail
