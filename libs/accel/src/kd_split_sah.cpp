// Full SAH over every candidate plane (Wald and Havran 2006): split events sorted once at the root and
// kept sorted down the tree, swept once per axis and node, with planar primitives placed on the cheaper
// side. Only straddling primitives get new (clipped) events, which are sorted among themselves and merged.
#include "kd_split.hpp"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <bit>
#include <cstdint>

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

namespace {

// An event's order as one integer: the position's bits made monotone (with -0 taken as +0, which compares
// equal to it), then the type.
std::uint64_t sort_key(const Event& e) {
    const auto bits = std::bit_cast<std::uint32_t>(e.position + 0.0f);
    const std::uint32_t ordered = (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
    return static_cast<std::uint64_t>(ordered) << 2 | e.type();
}

// Least-significant-digit radix sort on sort_key's 34 bits, three passes of 12, 11 and 11 bits: linear
// where std::sort's n log n comparisons dominate the root's sort (all primitives' events).
void radix_sort(std::vector<Event>& events) {
    constexpr int kPasses = 3;
    constexpr int kShift[kPasses] = {0, 12, 23};
    constexpr std::uint32_t kMask[kPasses] = {(1u << 12) - 1, (1u << 11) - 1, (1u << 11) - 1};
    const std::size_t n = events.size();
    std::vector<std::uint64_t> keys(n), keys_tmp(n);
    std::vector<Event> tmp(n);
    std::vector<std::size_t> count[kPasses];
    for (int p = 0; p < kPasses; ++p) count[p].assign(kMask[p] + 2, 0);
    for (std::size_t i = 0; i < n; ++i) {
        keys[i] = sort_key(events[i]);
        for (int p = 0; p < kPasses; ++p) ++count[p][((keys[i] >> kShift[p]) & kMask[p]) + 1];
    }
    Event* from = events.data();
    Event* to = tmp.data();
    std::uint64_t* from_keys = keys.data();
    std::uint64_t* to_keys = keys_tmp.data();
    for (int p = 0; p < kPasses; ++p) {
        std::vector<std::size_t>& offset = count[p];
        for (std::size_t b = 1; b < offset.size(); ++b) offset[b] += offset[b - 1];
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t slot = offset[(from_keys[i] >> kShift[p]) & kMask[p]]++;
            to[slot] = from[i];
            to_keys[slot] = from_keys[i];
        }
        std::swap(from, to);
        std::swap(from_keys, to_keys);
    }
    // An odd number of passes leaves the result in tmp.
    if (from != events.data()) events.swap(tmp);
}

}  // namespace

void sort_events(std::array<std::vector<Event>, 3>& events) {
    // Below a few thousand events the radix sort's buckets cost more than the comparisons they save.
    constexpr std::size_t kRadixMin = 4096;
    auto sort = [](std::vector<Event>& e) {
        if (e.size() >= kRadixMin)
            radix_sort(e);
        else
            std::sort(e.begin(), e.end());
    };
    // The root's sort comes before the build forks: its three axes are the only parallel work there.
    if (events[0].size() + events[1].size() + events[2].size() >= 3 * kRadixMin)
        tbb::parallel_invoke([&] { sort(events[0]); }, [&] { sort(events[1]); }, [&] { sort(events[2]); });
    else
        for (auto& e : events) sort(e);
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
