// Full SAH over every candidate plane (Wald and Havran 2006): split events sorted once at the root and
// kept sorted down the tree, swept once per axis and node, with planar primitives placed on the cheaper
// side. Only straddling primitives get new (clipped) events, which are sorted among themselves and merged.
#include "kd_split.hpp"

#include <tbb/parallel_invoke.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>

namespace rtlab::kd {

namespace {

// An event's order as one integer: the position's bits made monotone (with -0 taken as +0, which compares
// equal to it), then the type.
std::uint64_t sort_key(const Event& e) {
    const auto bits = std::bit_cast<std::uint32_t>(e.position + 0.0f);
    const std::uint32_t ordered = (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
    return static_cast<std::uint64_t>(ordered) << 2 | e.type();
}

// The event a key (sort_key over the slot) stands for. The key keeps the position up to the sign of zero:
// a zero is read back from the box.
Event decode(std::uint64_t key, std::span<const Prim> prims, int axis) {
    const auto slot = static_cast<std::uint32_t>(key & Event::kSlotMask);
    const auto type = static_cast<EventType>(key >> 30 & 3u);
    const auto ordered = static_cast<std::uint32_t>(key >> 32);
    auto position = std::bit_cast<float>((ordered & 0x80000000u) != 0 ? ordered & 0x7FFFFFFFu : ~ordered);
    if (position == 0.0f) position = type == kEnd ? prims[slot].box.hi[axis] : prims[slot].box.lo[axis];
    return {position, type, slot};
}

// The root's events of one axis, sorted: as keys (sort_key over the slot, 8 bytes) by a least-significant-
// digit radix sort on their top 34 bits, three passes of 12, 11 and 11 bits -- linear where std::sort's
// n log n comparisons dominate -- then decoded. The sort is stable: equal events keep the boxes' order.
void radix_sort_root(std::span<const Prim> prims, int axis, std::vector<Event>& events) {
    constexpr int kPasses = 3;
    constexpr int kShift[kPasses] = {30, 42, 53};
    constexpr std::uint32_t kMask[kPasses] = {(1u << 12) - 1, (1u << 11) - 1, (1u << 11) - 1};
    std::vector<std::uint64_t> keys;
    keys.reserve(2 * prims.size());
    for (std::size_t i = 0; i < prims.size(); ++i) {
        const float lo = prims[i].box.lo[axis], hi = prims[i].box.hi[axis];
        const auto slot = static_cast<std::uint32_t>(i);
        if (lo == hi) {
            keys.push_back(sort_key(Event(lo, kPlanar, slot)) << 30 | slot);
        } else {
            keys.push_back(sort_key(Event(lo, kStart, slot)) << 30 | slot);
            keys.push_back(sort_key(Event(hi, kEnd, slot)) << 30 | slot);
        }
    }
    const std::size_t n = keys.size();
    std::vector<std::size_t> count[kPasses];
    for (int p = 0; p < kPasses; ++p) count[p].assign(kMask[p] + 2, 0);
    for (const std::uint64_t key : keys)
        for (int p = 0; p < kPasses; ++p) ++count[p][((key >> kShift[p]) & kMask[p]) + 1];
    // Left uninitialized: each pass writes it all.
    const std::unique_ptr<std::uint64_t[]> tmp(new std::uint64_t[n]);
    std::uint64_t* from = keys.data();
    std::uint64_t* to = tmp.get();
    for (int p = 0; p < kPasses; ++p) {
        std::vector<std::size_t>& offset = count[p];
        for (std::size_t b = 1; b < offset.size(); ++b) offset[b] += offset[b - 1];
        for (std::size_t i = 0; i < n; ++i) to[offset[(from[i] >> kShift[p]) & kMask[p]]++] = from[i];
        std::swap(from, to);
    }
    events.resize(n);
    for (std::size_t i = 0; i < n; ++i) events[i] = decode(from[i], prims, axis);
}

}  // namespace

namespace {

// Below a few thousand events the radix sort's buckets cost more than the comparisons they save.
constexpr std::size_t kRadixMin = 4096;

// One axis's events of the boxes, in the boxes' order, start before end (the order of equal events after
// the stable radix sort).
void add_axis_events(std::span<const Prim> prims, int axis, std::vector<Event>& events) {
    events.reserve(2 * prims.size());
    for (std::size_t i = 0; i < prims.size(); ++i) {
        const float lo = prims[i].box.lo[axis], hi = prims[i].box.hi[axis];
        const auto slot = static_cast<std::uint32_t>(i);
        if (lo == hi) {
            events.emplace_back(lo, kPlanar, slot);
        } else {
            events.emplace_back(lo, kStart, slot);
            events.emplace_back(hi, kEnd, slot);
        }
    }
}

}  // namespace

constexpr std::size_t kKeptKeys = 1u << 11;

void sorted_events(std::span<const Prim> prims, std::span<const std::uint32_t> slots,
                   std::array<std::vector<Event>, 3>& events) {
    // Sorted as single integers -- sort_key over the slot -- which compare in one instruction where events
    // compare position, then type, with branches. A key keeps the position only up to the sign of zero, so
    // the position is read back from the box. Equal events come out by slot (std::sort of the events left
    // their order unspecified; it matters to nothing).
    thread_local std::vector<std::uint64_t> keys;
    for (int axis = 0; axis < 3; ++axis) {
        keys.clear();
        for (const std::uint32_t slot : slots) {
            const float lo = prims[slot].box.lo[axis], hi = prims[slot].box.hi[axis];
            if (lo == hi) {
                keys.push_back(sort_key(Event(lo, kPlanar, slot)) << 30 | slot);
            } else {
                keys.push_back(sort_key(Event(lo, kStart, slot)) << 30 | slot);
                keys.push_back(sort_key(Event(hi, kEnd, slot)) << 30 | slot);
            }
        }
        std::sort(keys.begin(), keys.end());
        std::vector<Event>& out = events[static_cast<std::size_t>(axis)];
        out.resize(keys.size());
        for (std::size_t k = 0; k < keys.size(); ++k) {
            const auto slot = static_cast<std::uint32_t>(keys[k] & Event::kSlotMask);
            const auto type = static_cast<EventType>(keys[k] >> 30 & 3u);
            const AABB& box = prims[slot].box;
            out[k] = Event(type == kEnd ? box.hi[axis] : box.lo[axis], type, slot);
        }
    }
    if (keys.capacity() > kKeptKeys) std::vector<std::uint64_t>().swap(keys);  // not held after the build
}

std::array<std::vector<Event>, 3> root_events(std::span<const Prim> prims) {
    // The root's events come before the build forks: its three axes, made and sorted, are the only
    // parallel work there.
    std::array<std::vector<Event>, 3> events;
    auto axis = [&](int a) {
        std::vector<Event>& e = events[static_cast<std::size_t>(a)];
        std::size_t count = 0;
        for (const Prim& p : prims) count += p.box.lo[a] == p.box.hi[a] ? 1 : 2;
        if (count >= kRadixMin) {
            radix_sort_root(prims, a, e);
        } else {
            add_axis_events(prims, a, e);
            std::sort(e.begin(), e.end());
        }
    };
    if (prims.size() >= kRadixMin)
        tbb::parallel_invoke([&] { axis(0); }, [&] { axis(1); }, [&] { axis(2); });
    else
        for (int a = 0; a < 3; ++a) axis(a);
    return events;
}

namespace {

/// \brief One axis's candidate planes of a node: positions strictly inside the box, with the primitives
/// wholly below each (n_left), wholly above (n_right) and lying in it (planar). Gathered by a scalar walk over
/// the events, then costed in loops the compiler vectorizes. The lists are the thread's, reused from node to
/// node (a sweep never waits on other tasks, so no other node's sweep runs on the thread meanwhile).
struct Candidates {
    float *position = nullptr, *cost_left = nullptr, *cost_right = nullptr;
    std::int32_t *n_left = nullptr, *n_right = nullptr, *planar = nullptr;
    std::size_t capacity = 0, size = 0;

    // Room for n candidates, left uninitialized (every one is written before it is read). The six lists
    // in two blocks: a node too large for the kept lists allocates them afresh, and six blocks each were
    // 31,722 mallocs in a bunny build, 12.4 M Ir of its 843 M (callgrind).
    void reserve(std::size_t n) {
        if (capacity >= n) return;
        floats.reset(new float[3 * n]);
        ints.reset(new std::int32_t[3 * n]);
        position = floats.get();
        cost_left = position + n;
        cost_right = cost_left + n;
        n_left = ints.get();
        n_right = n_left + n;
        planar = n_right + n;
        capacity = n;
    }

private:
    std::unique_ptr<float[]> floats;
    std::unique_ptr<std::int32_t[]> ints;
};

constexpr std::size_t kKeptCandidates = 1u << 10;

Candidates& thread_candidates(int axis) {
    thread_local std::array<Candidates, 3> candidates;
    return candidates[static_cast<std::size_t>(axis)];
}

// Set bits of a byte (the baseline x86-64 has no popcnt instruction).
constexpr std::array<std::uint8_t, 256> kBitCounts = [] {
    std::array<std::uint8_t, 256> counts{};
    for (unsigned b = 0; b < 256; ++b) counts[b] = static_cast<std::uint8_t>(std::popcount(b));
    return counts;
}();

/// Bits 0-7 for 8 consecutive events: the last event of its group (the next event's position differs), ends,
/// starts. `ev` holds 9 events (the 9th only for its position).
struct EightEvents {
    unsigned last, end, start;
};
inline EightEvents eight_events(const Event* ev) {
    EightEvents bits{0, 0, 0};
#if defined(__SSE2__)
    for (int half = 0; half < 2; ++half) {
        const auto* e = reinterpret_cast<const float*>(ev + 4 * half);
        const __m128 a = _mm_loadu_ps(e);      // position, key of events 0 and 1
        const __m128 b = _mm_loadu_ps(e + 4);  // of events 2 and 3
        const __m128 a_next = _mm_loadu_ps(e + 2);
        const __m128 b_next = _mm_loadu_ps(e + 6);
        const __m128 positions = _mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0));
        const __m128 next = _mm_shuffle_ps(a_next, b_next, _MM_SHUFFLE(2, 0, 2, 0));
        const __m128i types = _mm_srli_epi32(_mm_castps_si128(_mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1))), 30);
        const int shift = 4 * half;
        bits.last |= static_cast<unsigned>(_mm_movemask_ps(_mm_cmpneq_ps(positions, next))) << shift;
        bits.end |=
            static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(types, _mm_set1_epi32(kEnd)))))
            << shift;
        bits.start |=
            static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(types, _mm_set1_epi32(kStart)))))
            << shift;
    }
#else
    for (unsigned j = 0; j < 8; ++j) {
        bits.last |= (ev[j].position != ev[j + 1].position ? 1u : 0u) << j;
        bits.end |= (ev[j].type() == kEnd ? 1u : 0u) << j;
        bits.start |= (ev[j].type() == kStart ? 1u : 0u) << j;
    }
#endif
    return bits;
}

// The walk: the events at one position (a group) counted by type (end, planar, start); a candidate for each
// position inside the box. The events are read 8 at a time at fixed steps, each step's groups found from
// bit masks and counted from prefix counts. (Group by group, with a loop to each group's end, the next
// group's reads waited on the last one's count and the loop's exit was mispredicted about once a group:
// that set the pace of the whole sweep. A branch-free walk one event at a time ran three times the
// instructions.)
void gather(const std::vector<Event>& events, std::size_t n, float lo, float hi, Candidates& c) {
    c.reserve(events.size());
    const Event* ev = events.data();
    const std::size_t size = events.size();
    float* position_out = c.position;
    std::int32_t* n_left_out = c.n_left;
    std::int32_t* n_right_out = c.n_right;
    std::int32_t* planar_out = c.planar;
    const auto all = static_cast<std::int32_t>(n);
    std::size_t k = 0;
    // Before the current step: starts and planar events (left of the planes after them), ends and planar
    // (gone from the right at their plane), planar. And the same before the current group.
    std::int32_t left = 0, gone = 0, planar = 0;
    std::int32_t group_left = 0, group_planar = 0;
    std::size_t group_first = 0;
    for (std::size_t step = 0; step < size; step += 8) {
        // The last step's events are copied before NaN positions, which equal none.
        Event padded[9];
        const Event* e = ev + step;
        if (step + 9 > size) {
            for (std::size_t j = 0; j < 9; ++j)
                padded[j] = step + j < size ? ev[step + j] : Event(std::numeric_limits<float>::quiet_NaN(), kEnd, 0);
            e = padded;
        }
        const unsigned valid = size - step >= 8 ? 0xFFu : (1u << (size - step)) - 1;
        const EightEvents bits = eight_events(e);
        const unsigned starts = bits.start & valid, planars = ~(bits.start | bits.end) & valid;
        const unsigned lefts = starts | planars, gones = (bits.end & valid) | planars;
        for (unsigned lasts = bits.last & valid; lasts != 0; lasts &= lasts - 1) {
            const auto j = static_cast<unsigned>(std::countr_zero(lasts));
            const unsigned upto = (2u << j) - 1;
            const std::int32_t left_after = left + kBitCounts[lefts & upto];
            const std::int32_t planar_after = planar + kBitCounts[planars & upto];
            const float position = ev[group_first].position;
            if (position > lo && position < hi) {
                position_out[k] = position;
                n_left_out[k] = group_left;
                n_right_out[k] = all - (gone + kBitCounts[gones & upto]);
                planar_out[k] = planar_after - group_planar;
                ++k;
            }
            group_left = left_after;
            group_planar = planar_after;
            group_first = step + j + 1;
        }
        left += kBitCounts[lefts];
        gone += kBitCounts[gones];
        planar += kBitCounts[planars];
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
    const float* position = c.position;
    const std::int32_t* n_left = c.n_left;
    const std::int32_t* n_right = c.n_right;
    const std::int32_t* planar = c.planar;
    float* cost_left = c.cost_left;
    float* cost_right = c.cost_right;
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
    const float* cost_left = c.cost_left;
    const float* cost_right = c.cost_right;
    // The least cost first, four candidates at a time (costs are finite and positive, so the vector
    // minimum is the scalar one), then, only when it beats the best so far, its first candidate: the one
    // one candidate after the other with `<` finds.
    float least = best.cost;
    std::size_t k = 0;
#if defined(__SSE2__)
    __m128 least4 = _mm_set1_ps(least);
    for (; k + 4 <= c.size; k += 4)
        least4 = _mm_min_ps(least4, _mm_min_ps(_mm_loadu_ps(cost_left + k), _mm_loadu_ps(cost_right + k)));
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, least4);
    least = std::min(std::min(lanes[0], lanes[1]), std::min(lanes[2], lanes[3]));
#endif
    for (; k < c.size; ++k) least = std::min(least, std::min(cost_left[k], cost_right[k]));
    if (!(least < best.cost)) return;
    std::size_t chosen = 0;
    while (cost_left[chosen] != least && cost_right[chosen] != least) ++chosen;
    if (cost_left[chosen] == least)
        best = {axis, c.position[chosen], true, least};
    else
        best = {axis, c.position[chosen], false, least};
    // The counts the partition will find (it sorts the primitives by the very tests the events encode).
    best.below = c.n_left[chosen] + (best.planar_left ? c.planar[chosen] : 0);
    best.above = c.n_right[chosen] + (best.planar_left ? 0 : c.planar[chosen]);
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
    // A large node's lists are not kept: the thread would hold the root's (megabytes) after the build, and
    // their allocation is small beside such a node's sweep.
    if (c.capacity > kKeptCandidates) c = Candidates{};
}

}  // namespace

Split sweep_sah(const std::array<std::vector<Event>, 3>& events, std::size_t n, const AABB& box,
                const KdCostModel& cost) {
    Split best;
    best.cost = cost.leaf_cost(n);
    if (!(box.surface_area() > 0.0f)) return {};
    // The axes of a large node (the root's cut and the few below it, before the build has forked enough
    // to keep every thread busy) are swept in parallel, each from the leaf's cost, and then compared in
    // axis order: the first cheapest split over the axes, as one sweep after the other finds it.
    constexpr std::size_t kParallelEvents = 3 * 32768;
    if (events[0].size() + events[1].size() + events[2].size() >= kParallelEvents) {
        std::array<Split, 3> per_axis{best, best, best};
        tbb::parallel_invoke([&] { sweep_axis<0>(events[0], n, box, cost, per_axis[0]); },
                             [&] { sweep_axis<1>(events[1], n, box, cost, per_axis[1]); },
                             [&] { sweep_axis<2>(events[2], n, box, cost, per_axis[2]); });
        for (const Split& s : per_axis)
            if (s.cost < best.cost) best = s;
        return best;
    }
    sweep_axis<0>(events[0], n, box, cost, best);
    sweep_axis<1>(events[1], n, box, cost, best);
    sweep_axis<2>(events[2], n, box, cost, best);
    return best;
}

}  // namespace rtlab::kd
