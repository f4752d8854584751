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

namespace {

// One axis of the sweep; the axis is a template parameter so that the area terms that do not depend on
// the plane are computed once.
template <int Axis>
void sweep_axis(const std::vector<Event>& events, std::size_t n, const AABB& box, const AreaRatios& ratios,
                const KdCostModel& cost, Split& best) {
    const float lo = box.lo[Axis], hi = box.hi[Axis];
    if (!(hi > lo)) return;
    const Event* ev = events.data();
    const std::size_t size = events.size();
    std::size_t n_left = 0, n_right = n;
    for (std::size_t i = 0; i < size;) {
        const float position = ev[i].position;
        // The events at one position, counted by type (end, planar, start) in one pass.
        std::size_t count[3] = {0, 0, 0};
        do {
            ++count[ev[i].type()];
            ++i;
        } while (i < size && ev[i].position == position);
        const std::size_t ending = count[kEnd], planar = count[kPlanar], starting = count[kStart];
        n_right -= planar + ending;
        if (position > lo && position < hi) {
            float p_left, p_right;
            ratios.at<Axis>(position, p_left, p_right);
            const float with_left = cost.split_cost(p_left, p_right, n_left + planar, n_right);
            if (with_left < best.cost) best = {Axis, position, true, with_left};
            // Without planar primitives both placements cost the same: the left one already won or lost.
            if (planar > 0) {
                const float with_right = cost.split_cost(p_left, p_right, n_left, n_right + planar);
                if (with_right < best.cost) best = {Axis, position, false, with_right};
            }
        }
        n_left += starting + planar;
    }
}

}  // namespace

Split sweep_sah(const std::array<std::vector<Event>, 3>& events, std::size_t n, const AABB& box,
                const KdCostModel& cost) {
    Split best;
    best.cost = cost.leaf_cost(n);
    if (!(box.surface_area() > 0.0f)) return {};
    const AreaRatios ratios(box);
    sweep_axis<0>(events[0], n, box, ratios, cost, best);
    sweep_axis<1>(events[1], n, box, ratios, cost, best);
    sweep_axis<2>(events[2], n, box, ratios, cost, best);
    return best;
}

}  // namespace rtlab::kd
