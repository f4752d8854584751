#include <rtlab/core/error.hpp>
#include <rtlab/core/param_checks.hpp>

#include <charconv>
#include <cmath>

namespace rtlab {

void fail_param(const Params& params, std::string_view name, const std::string& problem) {
    throw ParamError(params.context() + ": parameter '" + std::string(name) + "' " + problem, {std::string(name)});
}

namespace {
// The shortest text that reads back as v, so that "got 1.0000001" is not shown as "got 1".
std::string number_text(float v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return {buffer, result.ptr};
}
}  // namespace

float positive_float(const Params& params, std::string_view name, float fallback, bool allow_zero) {
    const float v = params.get_float(name, fallback);
    const bool ok = std::isfinite(v) && (allow_zero ? v >= 0.0f : v > 0.0f);
    if (!ok)
        fail_param(params, name,
                   std::string("must be finite and ") + (allow_zero ? ">= 0" : "> 0") + ", got " + number_text(v));
    return v;
}

float float_in_range(const Params& params, std::string_view name, float fallback, float lo, float hi) {
    const float v = params.get_float(name, fallback);
    // Written so that NaN fails too.
    if (!(std::isfinite(v) && v >= lo && v <= hi))
        fail_param(params, name,
                   "must be finite and in [" + number_text(lo) + ", " + number_text(hi) + "], got " + number_text(v));
    return v;
}

int bounded_int(const Params& params, std::string_view name, int fallback, int lo, int hi) {
    const int v = params.get_int(name, fallback);
    if (v < lo || v > hi)
        fail_param(params, name,
                   "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + std::to_string(v));
    return v;
}

Vec2 get_vec2(const Params& params, std::string_view name, Vec2 fallback) {
    if (!params.has(name)) return fallback;
    const Params::List l = params.get_list(name);  // a single number comes back as a list of one
    if (l.size() != 1 && l.size() != 2) fail_param(params, name, "must be one number or a list of 2 numbers");
    const Vec2 v(static_cast<float>(l[0]), static_cast<float>(l.back()));
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) fail_param(params, name, "must be finite");
    return v;
}

std::string one_of(const Params& params, std::string_view name, std::string_view fallback,
                   std::initializer_list<std::string_view> allowed) {
    const std::string v = params.get_string(name, fallback);
    std::string list;
    for (std::string_view a : allowed) {
        if (v == a) return v;
        list += (list.empty() ? "" : ", ") + std::string(a);
    }
    fail_param(params, name, "must be one of " + list + ", got '" + v + "'");
}

RGB finite_rgb(const Params& params, std::string_view name, const RGB& fallback) {
    const RGB c = params.get_rgb(name, fallback);
    if (!c.is_finite()) fail_param(params, name, "must be finite");
    return c;
}

}  // namespace rtlab
