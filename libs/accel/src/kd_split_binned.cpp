// Binned SAH: 32 candidate planes per axis at equal spacing, counted in one pass over the primitives.
// The fast-build variant: a little worse trees, far less sorting.
#include "kd_split.hpp"

#include <algorithm>
#include <array>

namespace rtlab::kd {

Split find_split_binned(std::span<const Prim> prims, const AABB& box, const KdCostModel& cost) {
    constexpr int kBins = 32;
    Split best;
    best.cost = cost.leaf_cost(prims.size());
    if (box.surface_area() <= 0.0f) return {};
    const AreaRatios ratios(box);
    for (int axis = 0; axis < 3; ++axis) {
        const float lo = box.lo[axis], extent = box.hi[axis] - box.lo[axis];
        if (!(extent > 0.0f)) continue;
        const float scale = kBins / extent;
        std::array<std::size_t, kBins> starts{}, ends{};
        for (const Prim& p : prims) {
            const int s = std::clamp(static_cast<int>((p.box.lo[axis] - lo) * scale), 0, kBins - 1);
            const int e = std::clamp(static_cast<int>((p.box.hi[axis] - lo) * scale), 0, kBins - 1);
            ++starts[s];
            ++ends[e];
        }
        // Plane k sits at the lower border of bin k: left holds primitives starting in bins < k, right
        // those ending in bins >= k (a primitive spanning the plane counts on both sides).
        std::size_t n_left = 0, n_right = prims.size();
        for (int k = 1; k < kBins; ++k) {
            n_left += starts[k - 1];
            n_right -= ends[k - 1];
            const float position = lo + static_cast<float>(k) * (extent / kBins);
            if (!(position > box.lo[axis] && position < box.hi[axis])) continue;
            float p_left, p_right;
            ratios(axis, position, p_left, p_right);
            const float c = cost.split_cost(p_left, p_right, n_left, n_right);
            if (c < best.cost) best = {axis, position, true, c};
        }
    }
    return best;
}

}  // namespace rtlab::kd
