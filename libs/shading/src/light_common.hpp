#pragma once
// Helpers shared by the built-in lights (private to the shading library).
#include "builtin_params.hpp"

#include <cmath>

namespace rtlab::shading_detail {

/// A colour whose components are finite and >= 0.
RGB non_negative_rgb(const Params& params, std::string_view name, const RGB& fallback);
/// A non-zero finite direction, normalised.
Vec3 unit_direction(const Params& params, std::string_view name, const Vec3& fallback);
/// The sample of a point source at `position` seen from p (point and spot lights).
LightSample point_sample(const Point3& p, const Point3& position, const RGB& intensity, Convention c);

}  // namespace rtlab::shading_detail
