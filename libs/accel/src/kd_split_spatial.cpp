// The two splits that ignore cost: round-robin spatial median of the primitive centres, and the longest
// axis halved. Both stop at small leaves; the builder's depth cap stops them on clustered input.
#include "kd_split.hpp"

#include <algorithm>
#include <vector>

namespace rtlab::kd {

Split find_split_median(std::span<const Prim> prims, const AABB& box, int depth) {
    if (prims.size() <= kSpatialLeafSize) return {};
    for (int attempt = 0; attempt < 3; ++attempt) {
        const int axis = (depth + attempt) % 3;
        std::vector<float> centres;
        centres.reserve(prims.size());
        for (const Prim& p : prims) centres.push_back(0.5f * (p.box.lo[axis] + p.box.hi[axis]));
        auto mid = centres.begin() + static_cast<std::ptrdiff_t>(centres.size() / 2);
        std::nth_element(centres.begin(), mid, centres.end());
        const float position = *mid;
        if (position > box.lo[axis] && position < box.hi[axis]) return {axis, position, true, 0.0f};
    }
    return {};
}

Split find_split_midpoint(std::span<const Prim> prims, const AABB& box) {
    if (prims.size() <= kSpatialLeafSize) return {};
    const int axis = box.longest_axis();
    const float position = box.center()[axis];
    if (!(position > box.lo[axis] && position < box.hi[axis])) return {};
    return {axis, position, true, 0.0f};
}

}  // namespace rtlab::kd
