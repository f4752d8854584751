#pragma once
/// \brief The one kd-tree traversal: iterative, fixed stack, near child first, any-hit or closest-hit.
#include <rtlab/accel/kd_node.hpp>
#include <rtlab/core/ray.hpp>

#include <cmath>
#include <cstdint>

namespace rtlab {

/// Clips [ray.tmin, ray.tmax] to the box by slabs with the inverse direction that the walk needs anyway
/// (one division per axis rather than two). False for a miss, an empty box or a ray with a NaN or infinite
/// component. The near plane is picked by the direction's sign bit, never by comparing distances: a zero
/// component has an infinite inverse, so outside its slab both distances share one sign (a miss), inside
/// they span everything, and an origin on a slab plane gives that plane a NaN, which the comparisons below
/// ignore -- for +0 and -0 alike. The far distance grows by 2 gamma(3) as in AABB::intersect, so rounding
/// never clips a hit away.
inline bool clip_to_box(const AABB& box, const Ray& ray, const float* origin, const float* inv_dir, float& t0,
                        float& t1) {
    constexpr float far_scale = 1.0f + 2.0f * gamma_bound(3);
    t0 = ray.tmin;
    t1 = ray.tmax;
    bool finite = true;
    for (int a = 0; a < 3; ++a) {
        const bool negative = std::signbit(ray.direction[a]);
        const float t_near = ((negative ? box.hi[a] : box.lo[a]) - origin[a]) * inv_dir[a];
        const float t_far = ((negative ? box.lo[a] : box.hi[a]) - origin[a]) * inv_dir[a] * far_scale;
        t0 = t_near > t0 ? t_near : t0;
        t1 = t_far < t1 ? t_far : t1;
        finite &= std::isfinite(origin[a]) & std::isfinite(ray.direction[a]);
    }
    return finite & (t0 <= t1) & !box.is_empty();
}

namespace detail {

/// The walk of kd_traverse for rays whose direction has the sign bits of Octant (bit a set for a negative
/// component a, -0 included), over [tmin, tmax] already clipped to the root box.
template <bool AnyHit, unsigned Octant, class LeafTest>
bool kd_walk(const KdTreeData& tree, const Ray& ray, const float* origin, const float* inv_dir, float tmin, float tmax,
             LeafTest& test_leaf) {
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
            // Siblings are a pair at an even index: the near child is the pair's first or second node, the
            // above one where the direction is negative.
            const std::uint32_t side = (Octant >> axis) & 1u;
            const std::uint32_t near = node.children() | side, far = near ^ 1u;
            const std::uint32_t empty = node.empty_children();
            const bool near_empty = (empty >> side) & 1u, far_empty = (empty >> (side ^ 1u)) & 1u;
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

}  // namespace detail

/// Walks the tree front to back along the ray. `test_leaf(leaf, closest)` tests the primitives of a
/// non-empty leaf node against the ray restricted to (ray.tmin, closest), returns true on a hit and, for
/// closest-hit queries, lowers `closest` to the hit's t. With AnyHit the walk stops at the first hit.
///
/// Exact where naive traversals are not: the near child is chosen by the sign bit of the direction, so a
/// component of +0 or -0 (an infinite inverse) visits the side holding the origin; a ray lying in a split
/// plane gets a NaN plane distance, which no comparison accepts, and visits both children (primitives
/// touching the plane may sit on either side); tmin = tmax and negative tmin work; a NaN ray misses (the
/// root box test rejects it).
///
/// The walk is compiled once per octant of directions: the near side of each axis is then a constant, and
/// each octant's copy has branches of its own for the predictor to learn (bunny and dragon, random rays,
/// 1 thread: 1-6% faster than one walk for all directions).
template <bool AnyHit, class LeafTest>
bool kd_traverse(const KdTreeData& tree, const Ray& ray, LeafTest&& test_leaf) {
    if (tree.nodes.empty()) return false;
    float origin[3], inv_dir[3];
    unsigned octant = 0;
    for (int a = 0; a < 3; ++a) {
        origin[a] = ray.origin[a];
        inv_dir[a] = 1.0f / ray.direction[a];
        octant |= (std::signbit(ray.direction[a]) ? 1u : 0u) << a;
    }
    float tmin, tmax;
    if (!clip_to_box(tree.bounds, ray, origin, inv_dir, tmin, tmax)) return false;
    auto walk = [&]<unsigned Octant>() {
        return detail::kd_walk<AnyHit, Octant>(tree, ray, origin, inv_dir, tmin, tmax, test_leaf);
    };
    switch (octant) {
        case 0: return walk.template operator()<0>();
        case 1: return walk.template operator()<1>();
        case 2: return walk.template operator()<2>();
        case 3: return walk.template operator()<3>();
        case 4: return walk.template operator()<4>();
        case 5: return walk.template operator()<5>();
        case 6: return walk.template operator()<6>();
        default: return walk.template operator()<7>();
    }
}

}  // namespace rtlab
