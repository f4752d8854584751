// Full SAH over every candidate plane (Wald and Havran 2006): split events sorted once at the root and
// kept sorted down the tree, swept once per axis and node, with planar primitives placed on the cheaper
// side. Only straddling primitives get new (clipped) events, which are sorted among themselves and merged.
#include "kd_split.hpp"

#include <algorithm>

namespace rtlab::kd {

void add_events(const AABB& box, std::uint32_t slot, std::array<std::vector<Event>, 3>& events) {
    for (int axis = 0; axis < 3; ++axis) {
        if (box.lo[axis] == box.hi[axis]) {
            events[axis].push_back({box.lo[axis], kPlanar, slot});
        } else {
            events[axis].push_back({box.lo[axis], kStart, slot});
            events[axis].push_back({box.hi[axis], kEnd, slot});
        }
    }
}

void sort_events(std::array<std::vector<Event>, 3>& events) {
    for (auto& e : events) std::sort(e.begin(), e.end());
}

Split sweep_sah(const std::array<std::vector<Event>, 3>& events, std::size_t n, const AABB& box,
                const KdCostModel& cost) {
    Split best;
    best.cost = cost.leaf_cost(n);
    if (!(box.surface_area() > 0.0f)) return {};
    const AreaRatios ratios(box);
    for (int axis = 0; axis < 3; ++axis) {
        const float lo = box.lo[axis], hi = box.hi[axis];
        if (!(hi > lo)) continue;
        const Event* ev = events[axis].data();
        const std::size_t size = events[axis].size();
        std::size_t n_left = 0, n_right = n;
        for (std::size_t i = 0; i < size;) {
            const float position = ev[i].position;
            std::size_t ending = 0, planar = 0, starting = 0;
            while (i < size && ev[i].position == position && ev[i].type() == kEnd) ++ending, ++i;
            while (i < size && ev[i].position == position && ev[i].type() == kPlanar) ++planar, ++i;
            while (i < size && ev[i].position == position && ev[i].type() == kStart) ++starting, ++i;
            n_right -= planar + ending;
            if (position > lo && position < hi) {
                float p_left, p_right;
                ratios(axis, position, p_left, p_right);
                const float with_left = cost.split_cost(p_left, p_right, n_left + planar, n_right);
                if (with_left < best.cost) best = {axis, position, true, with_left};
                // Without planar primitives both placements cost the same: the left one already won or lost.
                if (planar > 0) {
                    const float with_right = cost.split_cost(p_left, p_right, n_left, n_right + planar);
                    if (with_right < best.cost) best = {axis, position, false, with_right};
                }
            }
            n_left += starting + planar;
        }
    }
    return best;
}

}  // namespace rtlab::kd
