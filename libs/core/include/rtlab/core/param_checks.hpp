#pragma once
/// \brief Checked reads of single parameters, shared by every object built from Params (textures,
/// materials, lights, plugins). Each throws rtlab::Error "<context>: parameter '<name>' <problem>".
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/core/params.hpp>

#include <initializer_list>
#include <string>
#include <string_view>

namespace rtlab {

/// Throws rtlab::Error "<params.context()>: parameter '<name>' <problem>".
[[noreturn]] void fail_param(const Params& params, std::string_view name, const std::string& problem);

/// A finite number > 0 (or >= 0 when allow_zero); the fallback when the parameter is absent.
float positive_float(const Params& params, std::string_view name, float fallback, bool allow_zero = false);
/// A finite number in [lo, hi] (roughness in [0, 1], say); the fallback when the parameter is absent.
float float_in_range(const Params& params, std::string_view name, float fallback, float lo, float hi);
/// An integer in [lo, hi]; the fallback when the parameter is absent.
int bounded_int(const Params& params, std::string_view name, int fallback, int lo, int hi);
/// One number (both components) or a list of two numbers, all finite.
Vec2 get_vec2(const Params& params, std::string_view name, Vec2 fallback);
/// One of the allowed words; the fallback when the parameter is absent.
std::string one_of(const Params& params, std::string_view name, std::string_view fallback,
                   std::initializer_list<std::string_view> allowed);
/// A colour (one number or a list of 3) with finite components.
RGB finite_rgb(const Params& params, std::string_view name, const RGB& fallback);

}  // namespace rtlab
