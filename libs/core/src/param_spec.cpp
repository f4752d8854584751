#include <rtlab/core/param_spec.hpp>

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace rtlab {

const char* param_kind_name(ParamKind kind) {
    switch (kind) {
        case ParamKind::number:
            return "number";
        case ParamKind::integer:
            return "integer";
        case ParamKind::boolean:
            return "true or false";
        case ParamKind::colour:
            return "colour";
        case ParamKind::vector:
            return "[x, y, z]";
        case ParamKind::numbers:
            return "list of numbers";
        case ParamKind::texture:
            return "colour or texture";
        case ParamKind::scalar:
            return "number or texture";
        case ParamKind::file:
            return "file";
        case ParamKind::folder:
            return "folder";
        case ParamKind::word:
            return "word";
        case ParamKind::text:
            return "string";
        case ParamKind::shape:
            return "shape name";
    }
    return "value";
}

ParamSpec& TypeSpec::add(std::string name, ParamKind kind, std::string doc) {
    if (find(name)) throw std::logic_error("parameter '" + name + "' declared twice");
    ParamSpec p;
    p.name = std::move(name);
    p.kind = kind;
    p.doc = std::move(doc);
    p.file_part = kind == ParamKind::file || kind == ParamKind::folder;
    m_params.push_back(std::move(p));
    return m_params.back();
}

TypeSpec& TypeSpec::extend(const std::vector<ParamSpec>& shared, std::string_view group) {
    for (ParamSpec p : shared) {
        if (find(p.name)) throw std::logic_error("parameter '" + p.name + "' declared twice");
        p.group = group;
        m_params.push_back(std::move(p));
    }
    return *this;
}

const ParamSpec* TypeSpec::find(std::string_view name) const {
    for (const ParamSpec& p : m_params)
        if (p.name == name) return &p;
    return nullptr;
}

ParamSpec& TypeSpec::at(std::string_view name) {
    for (ParamSpec& p : m_params)
        if (p.name == name) return p;
    throw std::logic_error("parameter '" + std::string(name) + "' is not declared");
}

std::vector<std::string> TypeSpec::names() const {
    std::vector<std::string> out;
    out.reserve(m_params.size());
    for (const ParamSpec& p : m_params) out.push_back(p.name);
    return out;
}

namespace {

std::string number_text(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return {buffer, result.ptr};
}

}  // namespace

std::string describe_param(const ParamSpec& p) {
    std::string what = param_kind_name(p.kind);
    if (p.kind == ParamKind::word && !p.words.empty()) {
        what.clear();
        for (const auto& w : p.words) what += (what.empty() ? "" : " | ") + w;
    }
    if (p.required)
        what += ", required";
    else if (!p.default_value.empty())
        what += ", default " + p.default_value;
    const bool bounded = std::isfinite(p.lo) || std::isfinite(p.hi);
    if (bounded && std::isinf(p.hi))
        what += ", >= " + number_text(p.lo);
    else if (bounded && std::isinf(p.lo))
        what += ", <= " + number_text(p.hi);
    else if (bounded)
        what += ", in [" + number_text(p.lo) + ", " + number_text(p.hi) + "]";
    if (!p.unit.empty()) what += ", " + p.unit;
    return p.name + " (" + what + ")" + (p.doc.empty() ? "" : ": " + p.doc);
}

std::string describe_params(const TypeSpec& spec, bool with_groups, std::string_view indent) {
    std::string out;
    for (const ParamSpec& p : spec.params()) {
        if (!with_groups && !p.group.empty()) continue;
        out += std::string(indent) + describe_param(p) + "\n";
    }
    return out;
}

}  // namespace rtlab
