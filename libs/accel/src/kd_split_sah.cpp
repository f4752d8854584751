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

/// \brief One axis's candidate planes of a node: positions strictly inside the box, with the primitives
/// wholly below each (n_left), wholly above (n_right) and lying in it (planar). Gathered by a scalar walk over
/// the events, then costed in loops the compiler vectorizes. The lists are the thread's, reused from node to
/// node (a sweep never waits on other tasks, so no other node's sweep runs on the thread meanwhile).
struct Candidates {
    std::vector<float> position, cost_left, cost_right;
    std::vector<std::int32_t> n_left, n_right, planar;
    std::size_t size = 0;

    void reserve(std::size_t n) {
        if (position.size() >= n) return;
        for (auto* v : {&position, &cost_left, &cost_right}) v->resize(n);
        for (auto* v : {&n_left, &n_right, &planar}) v->resize(n);
    }
};

Candidates& thread_candidates(int axis) {
    thread_local std::array<Candidates, 3> candidates;
    return candidates[static_cast<std::size_t>(axis)];
}

// The walk: the events at one position counted by type (end, planar, start) in one pass; a candidate for
// each position inside the box.
void gather(const std::vector<Event>& events, std::size_t n, float lo, float hi, Candidates& c) {
    c.reserve(events.size());
    const Event* ev = events.data();
    const std::size_t size = events.size();
    float* position_out = c.position.data();
    std::int32_t* n_left_out = c.n_left.data();
    std::int32_t* n_right_out = c.n_right.data();
    std::int32_t* planar_out = c.planar.data();
    std::size_t k = 0;
    std::size_t n_left = 0, n_right = n;
    for (std::size_t i = 0; i < size;) {
        const float position = ev[i].position;
        std::size_t count[3] = {0, 0, 0};
        do {
            ++count[ev[i].type()];
            ++i;
        } while (i < size && ev[i].position == position);
        const std::size_t ending = count[kEnd], planar = count[kPlanar], starting = count[kStart];
        n_right -= planar + ending;
        if (position > lo && position < hi) {
            position_out[k] = position;
            n_left_out[k] = static_cast<std::int32_t>(n_left);
            n_right_out[k] = static_cast<std::int32_t>(n_right);
            planar_out[k] = static_cast<std::int32_t>(planar);
            ++k;
        }
        n_left += starting + planar;
    }
    c.size = k;
}

// The costs of every candidate with its planar primitives on the left and on the right: AreaRatios and
// KdCostModel::split_cost written out over arrays, the very float operations in the same order (so the
// same bits; the counts, below 2^30, convert to the same floats from 32 bits as from 64). For Axis the
// extent varies, the other two are the box's.
template <int Axis>
void cost_candidates(const AABB& box, const KdCostModel& cost, Candidates& c) {
    const Vec3 extent = box.extent();
    const float inv = 1.0f / box.surface_area();
    const float lo = box.lo[Axis], hi = box.hi[Axis];
    const float traversal = cost.traversal(), intersection = cost.intersection();
    const float with_bonus = (1.0f - cost.empty_bonus()) * intersection, without_bonus = 1.0f * intersection;
    auto area = [&extent](float along) {
        const float x = Axis == 0 ? along : extent.x, y = Axis == 1 ? along : extent.y,
                    z = Axis == 2 ? along : extent.z;
        return 2.0f * (x * y + y * z + z * x);
    };
    const float* position = c.position.data();
    const std::int32_t* n_left = c.n_left.data();
    const std::int32_t* n_right = c.n_right.data();
    const std::int32_t* planar = c.planar.data();
    float* cost_left = c.cost_left.data();
    float* cost_right = c.cost_right.data();
    const std::size_t size = c.size;
    for (std::size_t k = 0; k < size; ++k) {
        const float p_left = area(position[k] - lo) * inv;
        const float p_right = area(hi - position[k]) * inv;
        const std::int32_t l = n_left[k], r = n_right[k], l_planar = l + planar[k], r_planar = r + planar[k];
        const float scale_left = (l_planar == 0 || r == 0) ? with_bonus : without_bonus;
        const float scale_right = (l == 0 || r_planar == 0) ? with_bonus : without_bonus;
        cost_left[k] =
            traversal + scale_left * (p_left * static_cast<float>(l_planar) + p_right * static_cast<float>(r));
        cost_right[k] =
            traversal + scale_right * (p_left * static_cast<float>(l) + p_right * static_cast<float>(r_planar));
    }
}

// The first cheapest candidate of one axis, planar primitives left before right at each plane, if cheaper
// than best. Without planar primitives both costs are equal, so the right one never wins there.
void pick(int axis, const Candidates& c, Split& best) {
    const float* cost_left = c.cost_left.data();
    const float* cost_right = c.cost_right.data();
    for (std::size_t k = 0; k < c.size; ++k) {
        if (cost_left[k] < best.cost) best = {axis, c.position[k], true, cost_left[k]};
        if (cost_right[k] < best.cost) best = {axis, c.position[k], false, cost_right[k]};
    }
}

template <int Axis>
void sweep_axis(const std::vector<Event>& events, std::size_t n, const AABB& box, const KdCostModel& cost,
                Split& best) {
    const float lo = box.lo[Axis], hi = box.hi[Axis];
    if (!(hi > lo)) return;
    Candidates& c = thread_candidates(Axis);
    gather(events, n, lo, hi, c);
    cost_candidates<Axis>(box, cost, c);
    pick(Axis, c, best);
}

}  // namespace

Split sweep_sah(const std::array<std::vector<Event>, 3>& events, std::size_t n, const AABB& box,
                const KdCostModel& cost) {
    Split best;
    best.cost = cost.leaf_cost(n);
    if (!(box.surface_area() > 0.0f)) return {};
    sweep_axis<0>(events[0], n, box, cost, best);
    sweep_axis<1>(events[1], n, box, cost, best);
    sweep_axis<2>(events[2], n, box, cost, best);
    return best;
}

}  // namespace rtlab::kd
