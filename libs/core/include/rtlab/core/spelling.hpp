#pragma once
/// \brief "Did you mean": the known name nearest to a mistyped one, for messages about unknown keys, types
/// and command-line flags.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// Edit distance (insertions, deletions, substitutions and swaps of neighbours), case-insensitive.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The name of `known` nearest to `typed` when it is near enough to be a typo (at most a third of the longer
/// name's letters differ, and at least one letter matches); nullopt otherwise. Ties go to the earlier name.
std::optional<std::string> nearest_name(std::string_view typed, const std::vector<std::string>& known);

/// "; did you mean 'NAME'?" for the nearest name, or "" when none is near.
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& known);

}  // namespace rtlab
