#pragma once
/// \brief A balanced kd-tree over points: k nearest neighbours and radius searches (photon maps).
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/math.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rtlab {

/// \brief One search result: the caller's index of the point and its squared distance to the query.
struct PointNeighbor {
    std::uint32_t index = 0;
    float distance2 = 0.0f;

    friend bool operator==(const PointNeighbor&, const PointNeighbor&) = default;
};

/// The squared distance every search uses: dx*dx + dy*dy + dz*dz in float, summed in that order (rtlab
/// compiles with -ffp-contract=off, so no FMA changes it). A brute-force search that uses it too agrees
/// with the tree bit for bit.
inline float squared_distance(const Point3& a, const Point3& b) {
    const Vec3 d = a - b;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

/// Order of the results of PointKdTree::within.
enum class PointOrder {
    tree,   ///< the order the search meets them: deterministic for a given input and query (see PointKdTree)
    index,  ///< by index: the same whatever the tree's layout
};

/// \brief A median-split kd-tree over points, stored as an implicit array (no child pointers).
///
/// Point i of the constructor's list is reported as index i. The node of an index range [lo, hi) is the
/// median at lo + (hi - lo) / 2, split on the axis of the largest extent of the range's points; its
/// children are [lo, mid) and [mid + 1, hi); ranges of at most kLeafSize points are leaves, scanned.
/// The layout is a function of the input alone (not of the thread count or of std::nth_element's
/// internals): medians are taken by (coordinate, index), a unique order, and leaves are sorted by index.
/// So "tree order" is reproducible: the same points and query visit the same points in the same order,
/// and a sum over a radius search in tree order is the same float every run.
///
/// Searches include a point when its squared_distance to the query is <= radius2 (inclusive: radius2 = 0
/// finds the points equal to the query; radius2 = infinity finds all). A negative or NaN radius2, or a
/// query with a NaN coordinate, finds nothing. Searches allocate nothing and are safe to run concurrently.
class PointKdTree {
public:
    static constexpr std::size_t kMaxPoints = (std::size_t{1} << 30) - 1;
    static constexpr std::uint32_t kLeafSize = 8;

    PointKdTree() = default;
    /// Builds the tree; threads = 0 lets oneTBB choose (the tree is the same for any count). Throws
    /// rtlab::Error naming the first point with a NaN or infinite coordinate, or when there are more than
    /// kMaxPoints points.
    explicit PointKdTree(std::span<const Point3> points, int threads = 0);

    std::size_t size() const { return m_nodes.size(); }
    bool empty() const { return m_nodes.empty(); }
    /// Bounds of all points (empty for an empty tree).
    const AABB& bounds() const { return m_bounds; }
    std::size_t bytes() const { return sizeof(*this) + m_nodes.capacity() * sizeof(Node); }

    /// The k = out.size() nearest points within radius2, written to out[0, count) sorted by (distance2,
    /// index); returns count (<= k). Among points at equal distances the smaller indices win, so the
    /// answer is exactly the k smallest (distance2, index) pairs. out is the search's heap: no allocation.
    std::size_t nearest(const Point3& query, float radius2, std::span<PointNeighbor> out) const;

    /// Calls f(index, distance2) for every point within radius2, in tree order.
    template <class F>
    void for_each_within(const Point3& query, float radius2, F&& f) const {
        search(query, radius2, [&](std::uint32_t index, float d2) {
            f(index, d2);
            return radius2;
        });
    }

    /// Appends every point within radius2 to out (what was in out stays), in the given order.
    void within(const Point3& query, float radius2, std::vector<PointNeighbor>& out,
                PointOrder order = PointOrder::tree) const;

private:
    struct Node {
        Point3 p;
        std::uint32_t index_axis;  // the caller's index << 2 | split axis (interior nodes only)

        std::uint32_t index() const { return index_axis >> 2; }
        int axis() const { return static_cast<int>(index_axis & 3u); }
    };

    static void build(std::span<Node> nodes);

    /// Visits every point whose squared distance is <= the bound: visit(index, d2) returns the new bound,
    /// never larger (k-NN shrinks it as its heap fills). Near child first; a far child is skipped when its
    /// splitting plane is farther than the bound. Sound in float: rounding is monotone, so a point beyond
    /// the plane never gets a squared distance below the plane's rounded (q - split)^2.
    template <class Visit>
    void search(const Point3& q, float bound, Visit&& visit) const;

    std::vector<Node> m_nodes;
    AABB m_bounds;
};

template <class Visit>
void PointKdTree::search(const Point3& q, float bound, Visit&& visit) const {
    struct Pending {
        std::uint32_t lo, hi;
        float plane2;
    };
    // At most one pending far child per level, and a tree of at most 2^30 points is under 30 levels deep.
    Pending stack[32];
    int pending = 0;
    std::uint32_t lo = 0;
    std::uint32_t hi = static_cast<std::uint32_t>(m_nodes.size());
    for (;;) {
        if (hi - lo <= kLeafSize) {
            for (std::uint32_t i = lo; i < hi; ++i) {
                const float d2 = squared_distance(q, m_nodes[i].p);
                if (d2 <= bound) bound = visit(m_nodes[i].index(), d2);
            }
        } else {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            const Node& node = m_nodes[mid];
            const float d2 = squared_distance(q, node.p);
            if (d2 <= bound) bound = visit(node.index(), d2);
            // Left holds coordinates <= the split, right >= it (equal ones may be on either side).
            const float diff = q[node.axis()] - node.p[node.axis()];
            const float plane2 = diff * diff;
            const bool left_near = diff < 0.0f;
            if (plane2 <= bound) stack[pending++] = left_near ? Pending{mid + 1, hi, plane2} : Pending{lo, mid, plane2};
            if (left_near)
                hi = mid;
            else
                lo = mid + 1;
            continue;
        }
        do {
            if (pending == 0) return;
            --pending;
        } while (!(stack[pending].plane2 <= bound));
        lo = stack[pending].lo;
        hi = stack[pending].hi;
    }
}

}  // namespace rtlab
