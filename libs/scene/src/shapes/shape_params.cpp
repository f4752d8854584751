#include "shape_params.hpp"

#include <string>

namespace rtlab::scene_detail {

Vec3 vec3_param(const Params& p, std::string_view name, const Vec3& fallback) {
    if (!p.has(name)) return fallback;
    const Params::List l = p.get_list(name);
    if (l.size() != 3) fail_param(p, name, "must be a list of 3 numbers, not " + std::to_string(l.size()));
    const Vec3 v(static_cast<float>(l[0]), static_cast<float>(l[1]), static_cast<float>(l[2]));
    if (!is_finite(v)) fail_param(p, name, "must be finite (a float)");
    return v;
}

Vec3 required_vec3(const Params& p, std::string_view name) {
    if (!p.has(name)) fail_param(p, name, "is missing");
    return vec3_param(p, name, Vec3(0.0f));
}

}  // namespace rtlab::scene_detail
