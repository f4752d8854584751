// The course's SAH: every primitive bound is a candidate plane, and each candidate's counts come from a
// scan over all primitives in the node: O(N^2) per node. Kept to chart build time against kd-sah.
#include "kd_split.hpp"

namespace rtlab::kd {

Split find_split_naive(std::span<const Prim> prims, const AABB& box, const KdCostModel& cost) {
    Split best;
    best.cost = cost.leaf_cost(prims.size());
    if (box.surface_area() <= 0.0f) return {};
    const AreaRatios ratios(box);
    for (int axis = 0; axis < 3; ++axis) {
        for (const Prim& candidate : prims) {
            for (const float position : {candidate.box.lo[axis], candidate.box.hi[axis]}) {
                if (!(position > box.lo[axis] && position < box.hi[axis])) continue;
                std::size_t n_left = 0, n_right = 0;
                for (const Prim& p : prims) {
                    if (p.box.lo[axis] < position || (p.box.lo[axis] == position && p.box.hi[axis] == position))
                        ++n_left;
                    if (p.box.hi[axis] > position) ++n_right;
                }
                float p_left, p_right;
                ratios(axis, position, p_left, p_right);
                const float c = cost.split_cost(p_left, p_right, n_left, n_right);
                if (c < best.cost) best = {axis, position, true, c};
            }
        }
    }
    return best;
}

}  // namespace rtlab::kd
