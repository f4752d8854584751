#pragma once
/// \brief The one kd-tree traversal: iterative, fixed stack, near child first, any-hit or closest-hit.
#include <rtlab/accel/kd_node.hpp>
#include <rtlab/core/box_ray.hpp>
#include <rtlab/core/ray.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rtlab {

/// Relative margin by which the walk widens each child's interval at a split plane. A plane distance is
/// (split - origin) * (1 / direction), three roundings (gamma(3) relative); an interval's ends are such
/// distances to other planes (or the root box). A hit lying on a split plane -- a vertex or an edge of a
/// tessellation, where the SAH puts its planes -- would otherwise fall between the two children when the
/// rounding says the ray leaves one before it enters the other. 8 gamma(3) covers both ends' errors with
/// room to spare; it widens which nodes are visited, never which hits count (those stay in the ray's own
/// (tmin, tmax)).
///
/// The walk applies it as one absolute margin per ray, kKdIntervalMargin * max(|t0|, |t1|) over the root
/// interval [t0, t1]: every interval end and every plane distance that is compared with one lies in that
/// interval (or the comparison decides nothing near it), so the absolute margin is at least the relative
/// one wherever it matters. Rather than end the near child one margin past the plane and start the far
/// child one margin before it, the walk ends the near child two margins past it and starts the far child
/// at it: every comparison of a plane distance with an interval end then has the same two margins of slack
/// (the root's far end gets them too), and a node step pays one addition. A far child's start is then no
/// lower bound of the t of the hits in it, so the closest-hit walk skips a stacked node only when the hit
/// lies two margins before its start.
inline constexpr float kKdIntervalMargin = 8.0f * gamma_bound(3);

namespace detail {

/// f.template operator()<Octant>() with the octant (0..7, bit a set for a negative direction component a)
/// as a constant: the kd walks are compiled once per octant. f is inlined where it is a lambda marked
/// always_inline (the packet walk's, which must take the AVX2 target of its caller).
template <class F>
[[gnu::always_inline]] inline decltype(auto) with_octant(unsigned octant, F&& f) {
    switch (octant) {
        case 0:
            return f.template operator()<0u>();
        case 1:
            return f.template operator()<1u>();
        case 2:
            return f.template operator()<2u>();
        case 3:
            return f.template operator()<3u>();
        case 4:
            return f.template operator()<4u>();
        case 5:
            return f.template operator()<5u>();
        case 6:
            return f.template operator()<6u>();
        default:
            return f.template operator()<7u>();
    }
}

/// The walk of kd_traverse for rays whose direction has the sign bits of Octant (bit a set for a negative
/// component a, -0 included), over [tmin, tmax] already clipped to the root box.
template <bool AnyHit, unsigned Octant, class LeafTest>
bool kd_walk(const KdTreeData& tree, const Ray& ray, const BoxRay& box_ray, float tmin, float tmax,
             LeafTest& test_leaf) {
    // Two of the ray's absolute margins (see kKdIntervalMargin), by which a near child overlaps its far
    // sibling; +inf for an unbounded root interval, which makes every near child reach to the end.
    const float overlap = 2.0f * kKdIntervalMargin * std::max(std::abs(tmin), std::abs(tmax));
    tmax += overlap;
    const float* origin = box_ray.origin;
    const float* inv_dir = box_ray.inv;
    float closest = ray.tmax;
    // pop() skips a stacked node whose start lies past closest_reach (the closest hit plus two margins) and
    // ends the walk at one past closest_end. A node pushed above another begins at most two margins past
    // it (it lies in the other's near sibling, which ends two margins past the plane where the other
    // begins), so once one begins past closest_end every node under it lies past closest_reach. That holds
    // unless a plane distance is NaN: a ray lying in a split plane, which needs a zero direction component
    // (an infinite inverse); such a ray pushes its far child over the whole interval, under nodes that begin
    // later, and its closest_end is +inf (it scans the whole stack). Both updated on the rare hit. Ending early
    // rather than scanning every ray's stack saves 3.8% of the closest-hit instructions on primary rays and
    // 1.2% on random rays (bunny, kd-sah, callgrind).
    const float end_slack =
        std::isinf(inv_dir[0]) | std::isinf(inv_dir[1]) | std::isinf(inv_dir[2]) ? kInfinity : overlap;
    float closest_reach = closest + overlap, closest_end = closest_reach + end_slack;

    struct Entry {
        std::uint32_t node;
        float tmin, tmax;
    };
    Entry stack[64];  // deeper than any tree the builders make (their depth cap is 60)
    Entry* top = stack;
    const KdNode* nodes = tree.nodes.data();
    std::uint32_t index = 0;
    bool hit = false;
    // Takes the next node from the stack; false when the walk is over.
    auto pop = [&]() {
        while (top != stack) {
            --top;
            if constexpr (!AnyHit) {
                if (closest_reach < top->tmin) [[unlikely]] {
                    if (closest_end < top->tmin) return false;
                    continue;
                }
            }
            index = top->node;
            tmin = top->tmin;
            tmax = top->tmax;
            return true;
        }
        return false;
    };
    // Per axis, for this octant: the bits of empty_children() that flag the near and the far child, read
    // from a table instead of shifted by the side (bunny, kd-sah, callgrind: 0.3-2.0% fewer instructions). The
    // near side itself stays a shift: it lies on the chain from one node's load to the next, where a table
    // load made primary rays slower (bunny, 1 thread, same-run ratio to Embree, loaded machine: 0.80 against
    // 0.82 closest, 0.84 against 0.88 any-hit). Constants where all three axes have one side: a table there
    // ran 20-24% more instructions in the walks of octants 0 and 7 than the shifts GCC folds.
    static constexpr std::uint32_t kSide[3] = {Octant & 1u, (Octant >> 1) & 1u, (Octant >> 2) & 1u};
    static constexpr std::uint32_t kNearEmpty[3] = {1u << kSide[0], 1u << kSide[1], 1u << kSide[2]};
    static constexpr std::uint32_t kFarEmpty[3] = {2u >> kSide[0], 2u >> kSide[1], 2u >> kSide[2]};
    constexpr bool kOneSide = Octant == 0 || Octant == 7;
    const auto side_of = [](std::uint32_t axis) { return kOneSide ? kSide[0] : (Octant >> axis) & 1u; };
    const auto near_empty_of = [](std::uint32_t axis) { return kOneSide ? kNearEmpty[0] : kNearEmpty[axis]; };
    const auto far_empty_of = [](std::uint32_t axis) { return kOneSide ? kFarEmpty[0] : kFarEmpty[axis]; };
    for (;;) {
        const KdNode node = nodes[index];
        if (!node.is_leaf()) {
            // The next node follows from the node alone while the branches below are predicted: the near
            // child, unless the plane lies before the interval or the near child is an empty leaf. The step
            // then waits on the node load only, not on the plane distance. [[unlikely]] is there to keep
            // the branch a branch (it is taken for about a third of the nodes): GCC otherwise makes it
            // branch-free, which chains every step on the division and the comparison and was 12-17% slower
            // on random rays (bunny, 1 thread). Empty children are never visited (or pushed). A NaN plane
            // distance (ray in the plane) fails every comparison: both children are visited, each over the
            // whole interval.
            const auto axis = static_cast<std::uint32_t>(node.axis());
            const std::uint32_t empty = node.empty_children();
            const float t_plane = (node.split() - origin[axis]) * inv_dir[axis];
            // The near child ends two margins past the plane, the far child starts at it (kKdIntervalMargin),
            // so a hit on the plane is inside both whatever the rounding. A sum, so an infinite plane
            // distance (a zero direction component) stays itself and NaN stays NaN.
            const float t_near_end = t_plane + overlap;
            // Siblings are a pair at an even index: the near child is the pair's first or second node, the
            // above one where the direction is negative.
            const std::uint32_t near = node.children() | side_of(axis);
            const bool reaches_far = !(t_plane > tmax) & ((empty & far_empty_of(axis)) == 0);
            // GCC makes this two branches, the plane test (mispredicted on 38% of the nodes in callgrind's
            // model, bunny random rays) and the empty near child (23%, but resolved from the node load
            // alone). One branch on both (their bits ORed behind an empty asm) cut callgrind's mispredicts
            // in the walk from 16.6 to 15.7 a ray, ran 75 more instructions and was slower in each of 3
            // paired rounds (bunny, 1 thread, ratio to Embree 0.58-0.68 against 0.68-0.77 closest,
            // 0.55-0.59 against 0.58-0.66 any-hit; loaded machine).
            // Also tried and reverted, measured against this step in one process (a second kd-sah accelerator
            // on the same tree with the variant, the two alternating, best of 9 rounds of 100k random rays,
            // 1 thread; the same step on both sides read 0.96-1.03): (1) nodes with an empty child taken
            // apart, the interval clipped to the other child's side with no branch on the plane (min/max
            // with 0 or +-inf added from a table) and one branch on an empty result: callgrind 969 -> 933 /
            // 927 -> 875 instructions a ray closest / any-hit but 16.6 -> 19.4 / 15.8 -> 18.1 mispredicts,
            // and 0.89-0.98x closest, 0.94-1.01x any-hit (bunny), 0.93-0.99x / 0.97-1.02x (dragon). (2) The
            // whole step branch-free but for "neither child" (near or far picked by an index xor and table
            // adders, forced with an empty asm): 0.86-0.87x closest, 0.85-0.89x any-hit (bunny), which
            // confirms the comment above: the chain through the plane distance costs more than the
            // mispredicts it saves.
            if ((t_near_end < tmin) | ((empty & near_empty_of(axis)) != 0)) [[unlikely]] {
                if (!reaches_far) [[unlikely]] {
                    if (!pop()) break;
                    continue;
                }
                tmin = t_plane > tmin ? t_plane : tmin;
                index = near ^ 1u;
                continue;
            }
            // The far child is written always and kept by moving the top, and the near child's end is
            // one minss (GCC 12, every octant): no branch on the data. Written in this form, both ends are
            // computed here, on this path only (computed before the branch, for every node, they ran 3.8%
            // more closest-hit instructions on bunny random rays, callgrind).
            *top = {near ^ 1u, t_plane > tmin ? t_plane : tmin, tmax};
            top += reaches_far;
            tmax = t_near_end < tmax ? t_near_end : tmax;
            index = near;
            continue;
        }
        // Not done: asking for a leaf's cache lines before its leaf test, through a prefetch hook of the
        // leaf test. At each push for a far child that is a leaf: 17% more walk instructions and 4 more
        // mispredicts a ray (bunny, closest-hit, callgrind). At each leaf for the leaf on top of the
        // stack: 1.6-3% more, +0.3 / +5.8 mispredicts closest / any-hit, and no faster in three paired
        // rounds (bunny, 1 thread: 0.61 against 0.62 closest, 0.60 against 0.68 any-hit, medians).
        if (node.primitive_count() != 0 && test_leaf(node, closest)) {
            hit = true;
            if constexpr (AnyHit) return true;
            closest_reach = closest + overlap;
            closest_end = closest_reach + end_slack;
        }
        if (!pop()) break;
    }
    return hit;
}

}  // namespace detail

/// Walks the tree front to back along the ray. `test_leaf(leaf, closest)` tests the primitives of a
/// non-empty leaf node against the ray restricted to (ray.tmin, closest), returns true on a hit and, for
/// closest-hit queries, lowers `closest` to the hit's t. With AnyHit the walk stops at the first hit.
///
/// Exact where naive traversals are not: the near child is chosen by the sign bit of the direction, so a
/// component of +0 or -0 (an infinite inverse) visits the side holding the origin; a ray lying in a split
/// plane gets a NaN plane distance, which no comparison accepts, and visits both children (primitives
/// touching the plane may sit on either side); tmin = tmax and negative tmin work; a NaN ray misses (the
/// root box clip rejects it).
///
/// The walk is compiled once per octant of directions: the near side of each axis is then a constant, and
/// each octant's copy has branches of its own for the predictor to learn (bunny and dragon, random rays,
/// 1 thread: 1-6% faster than one walk for all directions).
template <bool AnyHit, class LeafTest>
bool kd_traverse(const KdTreeData& tree, const Ray& ray, LeafTest&& test_leaf) {
    if (tree.nodes.empty() || tree.bounds.is_empty() || !is_finite(ray.origin) || !is_finite(ray.direction))
        return false;
    const BoxRay box_ray(ray);
    float tmin, tmax;
    if (!box_ray.clip(tree.bounds, ray.tmax, tmin, tmax)) return false;
    const unsigned octant = box_ray.negative[0] | box_ray.negative[1] << 1 | box_ray.negative[2] << 2;
    return detail::with_octant(octant, [&]<unsigned Octant>() {
        return detail::kd_walk<AnyHit, Octant>(tree, ray, box_ray, tmin, tmax, test_leaf);
    });
}

}  // namespace rtlab
