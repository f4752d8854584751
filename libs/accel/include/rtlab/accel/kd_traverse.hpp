#pragma once
/// \brief The one kd-tree traversal: iterative, fixed stack, near child first, any-hit or closest-hit.
#include <rtlab/accel/kd_node.hpp>
#include <rtlab/core/ray.hpp>

#include <cstdint>

namespace rtlab {

/// Walks the tree front to back along the ray. `test(primitive, closest)` tests one primitive against the
/// ray restricted to (ray.tmin, closest), returns true on a hit and, for closest-hit queries, lowers
/// `closest` to the hit's t. With AnyHit the walk stops at the first hit.
///
/// Exact where naive traversals are not: a direction component of +0 or -0 visits the side holding the
/// origin, a ray lying in a split plane visits both children, tmin = tmax and negative tmin work, and a
/// NaN ray misses (the root box test rejects it).
template <bool AnyHit, class PrimitiveTest>
bool kd_traverse(const KdTreeData& tree, const Ray& ray, PrimitiveTest&& test) {
    if (tree.nodes.empty()) return false;
    const auto range = tree.bounds.intersect(ray);
    if (!range) return false;
    float tmin = range->min, tmax = range->max;
    float closest = ray.tmax;
    const Vec3 inv_dir = 1.0f / ray.direction;

    struct Entry {
        std::uint32_t node;
        float tmin, tmax;
    };
    Entry stack[64];
    int top = 0;
    std::uint32_t index = 0;
    bool hit = false;
    for (;;) {
        if constexpr (!AnyHit) {
            if (closest < tmin) break;  // the closest hit lies before everything still to visit
        }
        const KdNode& node = tree.nodes[index];
        if (!node.is_leaf()) {
            const int axis = node.axis();
            const float split = node.split();
            const float o = ray.origin[axis], d = ray.direction[axis];
            const std::uint32_t below = index + 1, above = node.above_child();
            if (d == 0.0f) {
                if (o < split) index = below;
                else if (o > split) index = above;
                else {  // lying in the split plane: primitives touching it may sit on either side
                    stack[top++] = {above, tmin, tmax};
                    index = below;
                }
                continue;
            }
            const float t_plane = (split - o) * inv_dir[axis];
            const std::uint32_t near = d > 0.0f ? below : above, far = d > 0.0f ? above : below;
            if (t_plane > tmax) {
                index = near;
            } else if (t_plane < tmin) {
                index = far;
            } else {
                stack[top++] = {far, t_plane, tmax};
                index = near;
                tmax = t_plane;
            }
            continue;
        }
        const std::uint32_t count = node.primitive_count();
        if (count == 1) {
            if (test(node.primitive_offset(), closest)) {
                hit = true;
                if constexpr (AnyHit) return true;
            }
        } else {
            const std::uint32_t* primitives = tree.primitive_indices.data() + node.primitive_offset();
            for (std::uint32_t i = 0; i < count; ++i) {
                if (test(primitives[i], closest)) {
                    hit = true;
                    if constexpr (AnyHit) return true;
                }
            }
        }
        if (top == 0) break;
        --top;
        index = stack[top].node;
        tmin = stack[top].tmin;
        tmax = stack[top].tmax;
    }
    return hit;
}

}  // namespace rtlab
