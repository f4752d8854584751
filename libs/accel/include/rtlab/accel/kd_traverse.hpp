#pragma once
/// \brief The one kd-tree traversal: iterative, fixed stack, near child first, any-hit or closest-hit.
#include <rtlab/accel/kd_node.hpp>
#include <rtlab/core/box_ray.hpp>
#include <rtlab/core/ray.hpp>

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
inline constexpr float kKdIntervalMargin = 8.0f * gamma_bound(3);

namespace detail {

/// t moved away from zero / towards zero by kKdIntervalMargin relative: products, so +-inf stays itself
/// and NaN stays NaN (never a NaN from inf - inf).
[[gnu::always_inline]] inline float kd_widen_up(float t) { return t * (1.0f + std::copysign(kKdIntervalMargin, t)); }
[[gnu::always_inline]] inline float kd_widen_down(float t) { return t * (1.0f - std::copysign(kKdIntervalMargin, t)); }

/// The walk of kd_traverse for rays whose direction has the sign bits of Octant (bit a set for a negative
/// component a, -0 included), over [tmin, tmax] already clipped to the root box.
template <bool AnyHit, unsigned Octant, class LeafTest>
bool kd_walk(const KdTreeData& tree, const Ray& ray, const BoxRay& box_ray, float tmin, float tmax,
             LeafTest& test_leaf) {
    const float* origin = box_ray.origin;
    const float* inv_dir = box_ray.inv;
    float closest = ray.tmax;

    struct Entry {
        std::uint32_t node;
        float tmin, tmax;
    };
    Entry stack[64];  // deeper than any tree the builders make (their depth cap is 60)
    int top = 0;
    const KdNode* nodes = tree.nodes.data();
    std::uint32_t index = 0;
    bool hit = false;
    // Takes the next node from the stack; false when the walk is over. A closest-hit walk skips the nodes
    // that begin past the closest hit, one at a time: the stack is not sorted by tmin. A ray lying in a
    // split plane (a NaN plane distance) pushes the far child over the whole interval, under the entries
    // that its near child then pushes with larger tmin, so a hit before those says nothing about it.
    auto pop = [&]() {
        while (top != 0) {
            --top;
            if constexpr (!AnyHit)
                if (closest < stack[top].tmin) continue;
            index = stack[top].node;
            tmin = stack[top].tmin;
            tmax = stack[top].tmax;
            return true;
        }
        return false;
    };
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
            const int axis = node.axis();
            const float t_plane = (node.split() - origin[axis]) * inv_dir[axis];
            // The near child ends a little past the plane and the far child starts a little before it
            // (kKdIntervalMargin), so a hit on the plane is inside both whatever the rounding.
            const float t_near_end = kd_widen_up(t_plane), t_far_start = kd_widen_down(t_plane);
            // Siblings are a pair at an even index: the near child is the pair's first or second node, the
            // above one where the direction is negative.
            const std::uint32_t side = (Octant >> axis) & 1u;
            const std::uint32_t near = node.children() | side, far = near ^ 1u;
            const std::uint32_t empty = node.empty_children();
            const bool near_empty = (empty >> side) & 1u, far_empty = (empty >> (side ^ 1u)) & 1u;
            const bool reaches_far = !(t_far_start > tmax) & !far_empty;
            if ((t_near_end < tmin) | near_empty) [[unlikely]] {
                if (!reaches_far) [[unlikely]] {
                    if (!pop()) break;
                    continue;
                }
                tmin = t_far_start > tmin ? t_far_start : tmin;
                index = far;
                continue;
            }
            stack[top] = {far, t_far_start > tmin ? t_far_start : tmin, tmax};
            top += reaches_far;
            tmax = t_near_end < tmax ? t_near_end : tmax;
            index = near;
            continue;
        }
        if (node.primitive_count() != 0 && test_leaf(node, closest)) {
            hit = true;
            if constexpr (AnyHit) return true;
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
    auto walk = [&]<unsigned Octant>() {
        return detail::kd_walk<AnyHit, Octant>(tree, ray, box_ray, tmin, tmax, test_leaf);
    };
    switch (octant) {
        case 0:
            return walk.template operator()<0>();
        case 1:
            return walk.template operator()<1>();
        case 2:
            return walk.template operator()<2>();
        case 3:
            return walk.template operator()<3>();
        case 4:
            return walk.template operator()<4>();
        case 5:
            return walk.template operator()<5>();
        case 6:
            return walk.template operator()<6>();
        default:
            return walk.template operator()<7>();
    }
}

}  // namespace rtlab
