#pragma once
// Private to the scene loader: checked reads of single JSON values. Each reports what is wrong at its JSON
// pointer and returns nullopt, so that the loader goes on and reports every problem of a file in one pass.
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>

#include "scene_json.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab::scene_detail {

bool expect_object(Diagnostics& diag, const Json& v, const std::string& p, const std::string& what);
/// Every key of `obj` not in `allowed` is an error, with the nearest allowed key as a suggestion.
void check_keys(Diagnostics& diag, const Json& obj, const std::string& p, const std::vector<std::string>& allowed);
std::optional<double> read_number(Diagnostics& diag, const Json& v, const std::string& p, double lo, double hi);
std::optional<std::int64_t> read_integer(Diagnostics& diag, const Json& v, const std::string& p, std::int64_t lo,
                                         std::int64_t hi);
std::optional<std::string> read_string(Diagnostics& diag, const Json& v, const std::string& p);
std::optional<bool> read_boolean(Diagnostics& diag, const Json& v, const std::string& p);
std::optional<Vec3> read_vec3(Diagnostics& diag, const Json& v, const std::string& p);
/// One number (grey) or [r, g, b], finite and >= 0.
std::optional<RGB> read_colour(Diagnostics& diag, const Json& v, const std::string& p);

/// "a, b, c", or "(none)".
std::string join(const std::vector<std::string>& words);
/// The shortest text that reads back as v ("0", "64", "1e-06").
std::string number_text(double v);
/// "in [lo, hi]", ">= lo" or "<= hi" for a range with infinite ends.
std::string range_text(double lo, double hi);

}  // namespace rtlab::scene_detail
