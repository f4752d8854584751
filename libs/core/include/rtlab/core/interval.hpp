#pragma once
/// \brief A closed interval of floats; empty when min > max.
#include <rtlab/core/math.hpp>

#include <algorithm>

namespace rtlab {

/// \brief Closed interval [min, max]; the default one is empty.
struct Interval {
    float min = kInfinity;
    float max = -kInfinity;

    static constexpr Interval empty() { return {}; }
    static constexpr Interval everything() { return {-kInfinity, kInfinity}; }

    bool is_empty() const { return !(min <= max); }
    float size() const { return max - min; }
    bool contains(float x) const { return min <= x && x <= max; }
    /// Strictly inside: what a hit in (tmin, tmax) must satisfy.
    bool surrounds(float x) const { return min < x && x < max; }
    float clamp(float x) const { return std::clamp(x, min, max); }
    Interval expanded(float delta) const { return {min - delta, max + delta}; }
    Interval intersected(const Interval& o) const { return {std::max(min, o.min), std::min(max, o.max)}; }
    Interval united(const Interval& o) const { return {std::min(min, o.min), std::max(max, o.max)}; }
};

}  // namespace rtlab
