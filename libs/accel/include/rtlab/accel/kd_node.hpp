#pragma once
/// \brief The 8-byte kd-tree node and the flat tree the builders produce.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/core/aabb.hpp>

#include <cstdint>
#include <vector>

namespace rtlab {

/// \brief Interior node: split position, axis, index of its children (the below child, with the above child
/// right after it: a pair starting at an even index, so one cache line holds both) and which children are
/// empty leaves (the traversal then never visits them). Leaf: primitive count and either the one primitive
/// or an offset into the index array.
/// The 2 low bits of m_bits hold the axis (0..2) or 3 for a leaf. A leaf's 30 high bits hold its count;
/// an interior node's bit 2 says the below child is empty, bit 3 the above child, and its 28 high bits
/// hold the children's index.
class KdNode {
public:
    static KdNode interior(int axis, float split, std::uint32_t children, bool below_empty = false,
                           bool above_empty = false) {
        KdNode n;
        n.m_split = split;
        n.m_bits = (children << 4) | (static_cast<std::uint32_t>(above_empty) << 3) |
                   (static_cast<std::uint32_t>(below_empty) << 2) | static_cast<std::uint32_t>(axis);
        return n;
    }
    static KdNode leaf(std::uint32_t count, std::uint32_t first_or_offset) {
        KdNode n;
        n.m_offset = first_or_offset;
        n.m_bits = (count << 2) | 3u;
        return n;
    }

    bool is_leaf() const { return (m_bits & 3u) == 3u; }
    int axis() const { return static_cast<int>(m_bits & 3u); }
    float split() const { return m_split; }
    /// The below child; the above child is children() + 1.
    std::uint32_t children() const { return m_bits >> 4; }
    /// Bit 0: the below child is an empty leaf; bit 1: the above child is.
    std::uint32_t empty_children() const { return (m_bits >> 2) & 3u; }
    std::uint32_t primitive_count() const { return m_bits >> 2; }
    /// For a leaf with one primitive, the primitive itself; otherwise an offset into the index array.
    std::uint32_t primitive_offset() const { return m_offset; }

    static constexpr std::uint32_t kMaxIndex = (1u << 28) - 1;

private:
    union {
        float m_split;
        std::uint32_t m_offset;
    };
    std::uint32_t m_bits;
};
static_assert(sizeof(KdNode) == 8, "kd-tree nodes are 8 bytes");

/// \brief A built kd-tree: the root at 0 (node 1 is an empty leaf that only pads the root to a pair), then
/// sibling pairs in depth-first order; leaf primitive indices; root bounds.
struct KdTreeData {
    std::vector<KdNode> nodes;
    std::vector<std::uint32_t> primitive_indices;
    AABB bounds;
    AccelStats stats;
    /// Traversal stack depth needed (the tree's depth + 1).
    int max_depth = 0;
};

}  // namespace rtlab
