#include "scene_json.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <iterator>

namespace rtlab::scene_detail {

std::string pointer_append(const std::string& pointer, std::string_view token) {
    std::string out = pointer + "/";
    for (char c : token) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::string pointer_append(const std::string& pointer, std::size_t index) {
    return pointer + "/" + std::to_string(index);
}

void Diagnostics::set_text(std::string_view text) {
    m_line_starts.assign(1, 0);
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') m_line_starts.push_back(i + 1);
}

std::string Diagnostics::location(std::size_t offset) const {
    const auto it = std::upper_bound(m_line_starts.begin(), m_line_starts.end(), offset);
    const std::size_t line = static_cast<std::size_t>(it - m_line_starts.begin());
    const std::size_t column = offset - m_line_starts[line - 1] + 1;
    return std::to_string(line) + ":" + std::to_string(column);
}

std::string Diagnostics::position(const std::string& pointer) const {
    const auto it = m_offsets.find(pointer);
    return it == m_offsets.end() ? std::string() : location(it->second);
}

void Diagnostics::error(const std::string& pointer, const std::string& message) {
    const auto it = m_offsets.find(pointer);
    const std::size_t offset = it == m_offsets.end() ? SIZE_MAX : it->second;
    const std::string pos = it == m_offsets.end() ? std::string() : ":" + location(offset);
    m_lines.emplace_back(offset, m_file + pos + ": " + (pointer.empty() ? "(top level)" : pointer) + ": " + message);
}

void Diagnostics::error_at(std::size_t offset, const std::string& message) {
    m_lines.emplace_back(offset, m_file + ":" + location(offset) + ": " + message);
}

std::string Diagnostics::message() const {
    // In the order of the file, whatever order the loader found them in.
    auto lines = m_lines;
    std::stable_sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::string out;
    for (std::size_t i = 0; i < lines.size() && i < kMaxLines; ++i) out += (i ? "\n" : "") + lines[i].second;
    if (m_lines.size() > kMaxLines)
        out += "\n" + m_file + ": ... and " + std::to_string(m_lines.size() - kMaxLines) + " more errors";
    return out;
}

namespace {

// An input iterator over the text that tells the parser's owner how far the lexer has read, so that SAX
// events (which carry no position) can be placed.
class CountingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingIterator(const char* p, const char* base, std::size_t* consumed)
        : m_p(p), m_base(base), m_consumed(consumed) {}
    reference operator*() const { return *m_p; }
    CountingIterator& operator++() {
        ++m_p;
        if (m_consumed) *m_consumed = static_cast<std::size_t>(m_p - m_base);
        return *this;
    }
    CountingIterator operator++(int) {
        CountingIterator old = *this;
        ++*this;
        return old;
    }
    friend bool operator==(const CountingIterator& a, const CountingIterator& b) { return a.m_p == b.m_p; }
    friend bool operator!=(const CountingIterator& a, const CountingIterator& b) { return a.m_p != b.m_p; }

private:
    const char* m_p;
    const char* m_base;
    std::size_t* m_consumed;
};

// Builds the document like nlohmann's own DOM parser, and records for every value the offset where it
// starts: the first character after the previous token that is not white space, a separator or a comment.
class PositionSax {
public:
    PositionSax(std::string_view text, Diagnostics& diag, const std::size_t* consumed)
        : m_text(text), m_diag(diag), m_consumed(consumed) {}

    Json root;
    std::map<std::string, std::size_t> offsets;
    bool failed = false;

    bool null() { return value(nullptr); }
    bool boolean(bool b) { return value(b); }
    bool number_integer(Json::number_integer_t n) { return value(n); }
    bool number_unsigned(Json::number_unsigned_t n) { return value(n); }
    bool number_float(Json::number_float_t x, const std::string&) { return value(x); }
    bool string(std::string& s) { return value(s); }
    bool binary(Json::binary_t& b) { return value(b); }

    bool start_object(std::size_t) {
        if (too_deep()) return false;
        Json* node = value(Json::object_t{}) ? m_last : nullptr;
        m_stack.push_back({node, m_child_pointer, 0, m_child_discarded});
        return true;
    }
    bool end_object() {
        m_stack.pop_back();
        m_end = *m_consumed;
        return true;
    }
    bool start_array(std::size_t) {
        if (too_deep()) return false;
        Json* node = value(Json::array_t{}) ? m_last : nullptr;
        m_stack.push_back({node, m_child_pointer, 0, m_child_discarded});
        return true;
    }
    bool end_array() {
        m_stack.pop_back();
        m_end = *m_consumed;
        return true;
    }
    bool key(std::string& k) {
        const std::size_t start = token_start();
        if (k.size() > kMaxKeyLength) {
            m_diag.error_at(start, "a key of " + std::to_string(k.size()) + " characters: keys are at most " +
                                       std::to_string(kMaxKeyLength) + " characters long");
            failed = true;
            return false;
        }
        Frame& f = m_stack.back();
        auto& members = f.node->get_ref<Json::object_t&>();
        m_child_discarded = f.discarded;
        if (f.discarded) {  // inside a duplicate's value: kept nowhere, and its keys are not reported again
            members.emplace_back(k, nullptr);
            m_member = &members.back().second;
            m_end = *m_consumed;
            return true;
        }
        m_child_pointer = pointer_append(f.pointer, k);
        // Found through the offsets (a sorted map) rather than the object (an ordered list searched from the
        // start), so that an object with many keys loads in n log n, not n^2.
        if (const auto it = offsets.find(m_child_pointer); it != offsets.end()) {
            m_diag.error_at(start, (f.pointer.empty() ? std::string("(top level)") : f.pointer) + ": duplicate key '" +
                                       k + "' (first at " + m_diag.location(it->second) + ")");
            m_member = &m_discarded.emplace_back();  // the file is wrong anyway; the first value stays
            m_child_discarded = true;
        } else {
            offsets.emplace(m_child_pointer, start);
            members.emplace_back(k, nullptr);
            m_member = &members.back().second;
        }
        m_end = *m_consumed;
        return true;
    }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
        std::string what = e.what();
        // "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error ..." -> "syntax error ..."
        if (const auto column = what.find(", column "); column != std::string::npos) {
            if (const auto colon = what.find(": ", column); colon != std::string::npos) what = what.substr(colon + 2);
        } else if (what.starts_with("[json.exception.")) {
            // "[json.exception.out_of_range.406] number overflow parsing '1e999'" -> "number overflow ..."
            if (const auto close = what.find("] "); close != std::string::npos) what = what.substr(close + 2);
        }
        m_diag.error_at(position == 0 ? 0 : std::min(position - 1, m_text.size()), what);
        failed = true;
        return false;
    }

private:
    // Deeper nesting than any scene needs is refused at once: each value's pointer grows with its depth, so
    // a file of nested brackets would otherwise load in time quadratic in its size.
    bool too_deep() {
        if (m_stack.size() < kMaxNesting) return false;
        m_diag.error_at(token_start(), "lists and objects nested more than " + std::to_string(kMaxNesting) +
                                           " levels deep (a scene needs a handful)");
        failed = true;
        return true;
    }

    struct Frame {
        Json* node;
        std::string pointer;
        std::size_t index;
        bool discarded;  // the value of a duplicate key, or inside one
    };

    std::size_t token_start() const {
        std::size_t i = m_end;
        while (i < m_text.size()) {
            const char c = m_text[i];
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == ':') {
                ++i;
            } else if (c == '/' && i + 1 < m_text.size() && m_text[i + 1] == '/') {
                while (i < m_text.size() && m_text[i] != '\n') ++i;
            } else if (c == '/' && i + 1 < m_text.size() && m_text[i + 1] == '*') {
                const auto close = m_text.find("*/", i + 2);
                i = close == std::string_view::npos ? m_text.size() : close + 2;
            } else {
                break;
            }
        }
        return i;
    }

    template <class V>
    bool value(V&& v) {
        const std::size_t start = token_start();
        m_end = *m_consumed;
        if (m_stack.empty()) {
            root = Json(std::forward<V>(v));
            offsets[""] = start;
            m_child_pointer.clear();
            m_last = &root;
            return true;
        }
        Frame& f = m_stack.back();
        if (f.node->is_array()) {
            m_child_discarded = f.discarded;
            if (!f.discarded) {
                m_child_pointer = pointer_append(f.pointer, f.index++);
                offsets[m_child_pointer] = start;
            }
            f.node->emplace_back(std::forward<V>(v));
            m_last = &f.node->back();
        } else {
            *m_member = Json(std::forward<V>(v));
            m_last = m_member;
        }
        return true;
    }

    std::string_view m_text;
    Diagnostics& m_diag;
    const std::size_t* m_consumed;
    std::vector<Frame> m_stack;
    std::string m_child_pointer;
    Json* m_member = nullptr;
    Json* m_last = nullptr;
    std::deque<Json> m_discarded;  // values of duplicate keys (a deque: their addresses stay put)
    bool m_child_discarded = false;
    std::size_t m_end = 0;
};

}  // namespace

std::optional<Json> parse_json(std::string_view text, Diagnostics& diag) {
    diag.set_text(text);
    std::size_t consumed = 0;
    PositionSax sax(text, diag, &consumed);
    const char* base = text.data();
    CountingIterator first(base, base, &consumed), last(base + text.size(), base, nullptr);
    Json::sax_parse(first, last, &sax, nlohmann::detail::input_format_t::json, true, true);
    if (sax.failed) return std::nullopt;
    diag.set_offsets(std::move(sax.offsets));
    return std::move(sax.root);
}

std::string describe(const Json& v) {
    switch (v.type()) {
        case Json::value_t::null:
            return "null";
        case Json::value_t::boolean:
            return v.get<bool>() ? "true" : "false";
        case Json::value_t::string: {
            std::string s = v.get<std::string>();
            if (s.size() > 40) s = s.substr(0, 37) + "...";
            return "the string \"" + s + "\"";
        }
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
        case Json::value_t::number_float:
            return "the number " + v.dump();
        case Json::value_t::object:
            return "an object";
        case Json::value_t::array:
            return "a list of " + std::to_string(v.size()) + " value" + (v.size() == 1 ? "" : "s");
        default:
            return "a binary value";
    }
}

}  // namespace rtlab::scene_detail
