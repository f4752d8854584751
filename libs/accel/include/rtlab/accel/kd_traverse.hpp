#pragma once
/// \brief The one kd-tree traversal: iterative, fixed stack, near child first, any-hit or closest-hit.
#include <rtlab/accel/kd_node.hpp>
#include <rtlab/core/ray.hpp>

#include <cmath>
#include <cstdint>

namespace rtlab {

/// Walks the tree front to back along the ray. `test_leaf(leaf, closest)` tests the primitives of a
/// non-empty leaf node against the ray restricted to (ray.tmin, closest), returns true on a hit and, for
/// closest-hit queries, lowers `closest` to the hit's t. With AnyHit the walk stops at the first hit.
///
/// Exact where naive traversals are not: the near child is chosen by the sign bit of the direction, so a
/// component of +0 or -0 (an infinite inverse) visits the side holding the origin; a ray lying in a split
/// plane gets a NaN plane distance, which no comparison accepts, and visits both children (primitives
/// touching the plane may sit on either side); tmin = tmax and negative tmin work; a NaN ray misses (the
/// root box test rejects it).
template <bool AnyHit, class LeafTest>
bool kd_traverse(const KdTreeData& tree, const Ray& ray, LeafTest&& test_leaf) {
    if (tree.nodes.empty()) return false;
    const auto range = tree.bounds.intersect(ray);
    if (!range) return false;
    float tmin = range->min, tmax = range->max;
    float closest = ray.tmax;
    float origin[3], inv_dir[3];
    std::uint32_t flip[3];  // all ones where the above child comes first (a negative direction, -0 too)
    for (int a = 0; a < 3; ++a) {
        origin[a] = ray.origin[a];
        inv_dir[a] = 1.0f / ray.direction[a];
        flip[a] = std::signbit(ray.direction[a]) ? ~0u : 0u;
    }

    struct Entry {
        std::uint32_t node;
        float tmin, tmax;
    };
    Entry stack[64];  // deeper than any tree the builders make (their depth cap is 60)
    int top = 0;
    const KdNode* nodes = tree.nodes.data();
    std::uint32_t index = 0;
    bool hit = false;
    // Takes the next node from the stack; false when the walk is over.
    auto pop = [&]() {
        if (top == 0) return false;
        --top;
        index = stack[top].node;
        tmin = stack[top].tmin;
        tmax = stack[top].tmax;
        if constexpr (!AnyHit) return !(closest < tmin);  // else the closest hit lies before all that is left
        return true;
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
            const std::uint32_t below = index + 1, above = node.above_child();
            const std::uint32_t near = below ^ ((below ^ above) & flip[axis]), far = near ^ below ^ above;
            const std::uint32_t empty = node.empty_children(), near_side = flip[axis] & 1u;
            const bool near_empty = (empty >> near_side) & 1u, far_empty = (empty >> (near_side ^ 1u)) & 1u;
            const bool reaches_far = !(t_plane > tmax) & !far_empty;
            if ((t_plane < tmin) | near_empty) [[unlikely]] {
                if (!reaches_far) [[unlikely]] {
                    if (!pop()) break;
                    continue;
                }
                tmin = t_plane > tmin ? t_plane : tmin;
                index = far;
                continue;
            }
            stack[top] = {far, t_plane > tmin ? t_plane : tmin, tmax};
            top += reaches_far;
            tmax = t_plane < tmax ? t_plane : tmax;
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

}  // namespace rtlab
