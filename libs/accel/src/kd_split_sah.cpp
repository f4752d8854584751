// Full SAH over every candidate plane: sorted split events swept once per axis (Wald and Havran 2006),
// with planar primitives placed on the cheaper side. Events are sorted per node, so a build costs
// O(N log^2 N); the sweep itself is linear.
#include "kd_split.hpp"

#include <algorithm>
#include <vector>

namespace rtlab::kd {

namespace {
// Sorted by position, then end < planar < start: at one position, primitives ending there leave the
// right side before those starting there join the left.
enum EventType : std::uint8_t { kEnd = 0, kPlanar = 1, kStart = 2 };
struct Event {
    float position;
    EventType type;
    bool operator<(const Event& o) const { return position < o.position || (position == o.position && type < o.type); }
};
}  // namespace

Split find_split_sah(std::span<const Prim> prims, const AABB& box, const KdCostModel& cost) {
    Split best;
    best.cost = cost.leaf_cost(prims.size());
    const std::size_t n = prims.size();
    if (box.surface_area() <= 0.0f) return {};
    std::vector<Event> events;
    events.reserve(2 * n);
    for (int axis = 0; axis < 3; ++axis) {
        if (!(box.hi[axis] > box.lo[axis])) continue;
        events.clear();
        for (const Prim& p : prims) {
            if (p.box.lo[axis] == p.box.hi[axis]) {
                events.push_back({p.box.lo[axis], kPlanar});
            } else {
                events.push_back({p.box.lo[axis], kStart});
                events.push_back({p.box.hi[axis], kEnd});
            }
        }
        std::sort(events.begin(), events.end());
        std::size_t n_left = 0, n_right = n;
        for (std::size_t i = 0; i < events.size();) {
            const float position = events[i].position;
            std::size_t ending = 0, planar = 0, starting = 0;
            while (i < events.size() && events[i].position == position && events[i].type == kEnd) ++ending, ++i;
            while (i < events.size() && events[i].position == position && events[i].type == kPlanar) ++planar, ++i;
            while (i < events.size() && events[i].position == position && events[i].type == kStart) ++starting, ++i;
            n_right -= planar + ending;
            if (position > box.lo[axis] && position < box.hi[axis]) {
                float p_left, p_right;
                area_ratios(box, axis, position, p_left, p_right);
                const float with_left = cost.split_cost(p_left, p_right, n_left + planar, n_right);
                const float with_right = cost.split_cost(p_left, p_right, n_left, n_right + planar);
                if (with_left < best.cost) best = {axis, position, true, with_left};
                if (with_right < best.cost) best = {axis, position, false, with_right};
            }
            n_left += starting + planar;
        }
    }
    return best;
}

}  // namespace rtlab::kd
