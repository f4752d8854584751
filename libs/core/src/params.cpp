#include <rtlab/core/params.hpp>

#include <cmath>

namespace rtlab {

namespace {
const char* type_name(const Params::Value& v) {
    switch (v.index()) {
        case 0:
            return "a boolean";
        case 1:
            return "a number";
        case 2:
            return "a string";
        case 3:
            return "a list of numbers";
        default:
            return "an object";
    }
}
}  // namespace

Params& Params::set(std::string name, Value value) {
    m_values.insert_or_assign(std::move(name), std::move(value));
    return *this;
}

std::vector<std::string> Params::names() const {
    std::vector<std::string> out;
    for (const auto& [name, value] : m_values) out.push_back(name);
    return out;
}

void Params::note_lookup(std::string_view name) const {
    if (m_looked_up.find(name) == m_looked_up.end()) m_looked_up.emplace(name);
}

const Params::Value* Params::find(std::string_view name) const {
    note_lookup(name);
    auto it = m_values.find(name);
    if (it == m_values.end()) return nullptr;
    m_used.insert(it->first);
    return &it->second;
}

const Params::Value& Params::require(std::string_view name) const {
    const Value* v = find(name);
    if (!v) throw ParamError(m_context + ": missing parameter '" + std::string(name) + "'", {std::string(name)});
    return *v;
}

void Params::fail_type(std::string_view name, std::string_view expected) const {
    const Value* v = find(name);
    throw ParamError(m_context + ": parameter '" + std::string(name) + "' must be " + std::string(expected) + ", not " +
                         (v ? type_name(*v) : "missing"),
                     {std::string(name)});
}

float Params::get_float(std::string_view name) const {
    const Value& v = require(name);
    const auto* n = std::get_if<Number>(&v);
    if (!n) fail_type(name, "a number");
    return static_cast<float>(*n);
}

float Params::get_float(std::string_view name, float fallback) const { return has(name) ? get_float(name) : fallback; }

int Params::get_int(std::string_view name) const {
    const Value& v = require(name);
    const auto* n = std::get_if<Number>(&v);
    if (!n || std::trunc(*n) != *n || std::abs(*n) > 2147483647.0) fail_type(name, "an integer");
    return static_cast<int>(*n);
}

int Params::get_int(std::string_view name, int fallback) const { return has(name) ? get_int(name) : fallback; }

bool Params::get_bool(std::string_view name, bool fallback) const {
    if (!has(name)) return fallback;
    const auto* b = std::get_if<bool>(&require(name));
    if (!b) fail_type(name, "a boolean");
    return *b;
}

std::string Params::get_string(std::string_view name) const {
    const auto* s = std::get_if<std::string>(&require(name));
    if (!s) fail_type(name, "a string");
    return *s;
}

std::string Params::get_string(std::string_view name, std::string_view fallback) const {
    return has(name) ? get_string(name) : std::string(fallback);
}

Params::List Params::get_list(std::string_view name) const {
    const Value& v = require(name);
    if (const auto* n = std::get_if<Number>(&v)) return {*n};
    const auto* l = std::get_if<List>(&v);
    if (!l) fail_type(name, "a list of numbers");
    return *l;
}

Vec3 Params::get_vec3(std::string_view name) const {
    const auto* l = std::get_if<List>(&require(name));
    if (!l || l->size() != 3) fail_type(name, "a list of 3 numbers");
    return {static_cast<float>((*l)[0]), static_cast<float>((*l)[1]), static_cast<float>((*l)[2])};
}

Vec3 Params::get_vec3(std::string_view name, const Vec3& fallback) const {
    return has(name) ? get_vec3(name) : fallback;
}

RGB Params::get_rgb(std::string_view name) const {
    const Value& v = require(name);
    if (const auto* n = std::get_if<Number>(&v)) return RGB(static_cast<float>(*n));
    const auto* l = std::get_if<List>(&v);
    if (!l || l->size() != 3) fail_type(name, "a colour (one number or a list of 3)");
    return {static_cast<float>((*l)[0]), static_cast<float>((*l)[1]), static_cast<float>((*l)[2])};
}

RGB Params::get_rgb(std::string_view name, const RGB& fallback) const { return has(name) ? get_rgb(name) : fallback; }

void Params::check_all_used() const {
    std::string unused;
    std::vector<std::string> keys;
    for (const auto& [name, value] : m_values) {
        if (m_used.contains(name)) continue;
        unused += (unused.empty() ? "'" : ", '") + name + "'";
        keys.push_back(name);
    }
    if (!unused.empty())
        throw ParamError(m_context + ": unknown or unused parameter(s) " + unused, std::move(keys),
                         ParamError::Reason::unused);
}

}  // namespace rtlab
