#include "json_values.hpp"

#include <rtlab/core/spelling.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace rtlab::scene_detail {

std::string join(const std::vector<std::string>& words) {
    std::string out;
    for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
    return out.empty() ? "(none)" : out;
}

std::string number_text(double v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return {buffer, result.ptr};
}

std::string range_text(double lo, double hi) {
    if (std::isinf(lo) && std::isinf(hi)) return "finite";
    if (std::isinf(hi)) return ">= " + number_text(lo);
    if (std::isinf(lo)) return "<= " + number_text(hi);
    return "in [" + number_text(lo) + ", " + number_text(hi) + "]";
}

bool expect_object(Diagnostics& diag, const Json& v, const std::string& p, const std::string& what) {
    if (v.is_object()) return true;
    diag.error(p, "expected " + what + " (a JSON object), not " + describe(v));
    return false;
}

void check_keys(Diagnostics& diag, const Json& obj, const std::string& p, const std::vector<std::string>& allowed) {
    for (const auto& [key, value] : obj.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        diag.error(pointer_append(p, key),
                   "unknown key '" + key + "'" + did_you_mean(key, allowed) + "; expected one of: " + join(allowed));
    }
}

std::optional<double> read_number(Diagnostics& diag, const Json& v, const std::string& p, double lo, double hi) {
    if (!v.is_number()) {
        diag.error(p, "expected a number, not " + describe(v));
        return std::nullopt;
    }
    const double x = v.get<double>();
    if (!(x >= lo && x <= hi)) {
        diag.error(p, "must be " + range_text(lo, hi) + ", not " + v.dump());
        return std::nullopt;
    }
    return x;
}

std::optional<std::int64_t> read_integer(Diagnostics& diag, const Json& v, const std::string& p, std::int64_t lo,
                                         std::int64_t hi) {
    if (!v.is_number() || (v.is_number_float() && std::trunc(v.get<double>()) != v.get<double>())) {
        diag.error(p, "expected an integer, not " + describe(v));
        return std::nullopt;
    }
    const double x = v.get<double>();
    if (!(x >= static_cast<double>(lo) && x <= static_cast<double>(hi))) {
        diag.error(p,
                   "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + v.dump());
        return std::nullopt;
    }
    return v.is_number_unsigned() ? static_cast<std::int64_t>(v.get<std::uint64_t>()) : v.get<std::int64_t>();
}

std::optional<std::string> read_string(Diagnostics& diag, const Json& v, const std::string& p) {
    if (!v.is_string()) {
        diag.error(p, "expected a string, not " + describe(v));
        return std::nullopt;
    }
    return v.get<std::string>();
}

std::optional<bool> read_boolean(Diagnostics& diag, const Json& v, const std::string& p) {
    if (!v.is_boolean()) {
        diag.error(p, "expected true or false, not " + describe(v));
        return std::nullopt;
    }
    return v.get<bool>();
}

std::optional<Vec3> read_vec3(Diagnostics& diag, const Json& v, const std::string& p) {
    if (!v.is_array() || v.size() != 3 ||
        !std::all_of(v.begin(), v.end(), [](const Json& x) { return x.is_number(); })) {
        diag.error(p, "expected a list of 3 numbers [x, y, z], not " + describe(v));
        return std::nullopt;
    }
    const Vec3 out(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
    if (!is_finite(out)) {
        diag.error(p, "must be finite (representable as a float), not " + v.dump());
        return std::nullopt;
    }
    return out;
}

std::optional<RGB> read_colour(Diagnostics& diag, const Json& v, const std::string& p) {
    RGB c;
    if (v.is_number()) {
        c = RGB(v.get<float>());
    } else if (v.is_array() && v.size() == 3 &&
               std::all_of(v.begin(), v.end(), [](const Json& x) { return x.is_number(); })) {
        c = RGB(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
    } else {
        diag.error(p, "expected a colour (a number or a list of 3 numbers [r, g, b]), not " + describe(v));
        return std::nullopt;
    }
    if (!c.is_finite() || c.r < 0.0f || c.g < 0.0f || c.b < 0.0f) {
        diag.error(p, "a colour must be finite and >= 0, not " + v.dump());
        return std::nullopt;
    }
    return c;
}

}  // namespace rtlab::scene_detail
