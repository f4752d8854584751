#include <rtlab/accel/point_kd_tree.hpp>
#include <rtlab/core/error.hpp>

#include "thread_arena.hpp"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <sstream>

namespace rtlab {

namespace {

// Below this many points a subtree is built on the calling thread: a task would cost more than it saves.
constexpr std::size_t kParallelPoints = std::size_t{1} << 14;

// The k-NN heap's order: a before b when it is nearer, or as near with a smaller index. The heap keeps
// its last element (in this order) at the front, the one a better candidate replaces.
bool before(const PointNeighbor& a, const PointNeighbor& b) {
    return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
}

// Replaces the heap's front by x and sifts it down: one pass where pop_heap + push_heap take two.
void replace_front(std::span<PointNeighbor> heap, const PointNeighbor& x) {
    std::size_t i = 0;
    for (;;) {
        std::size_t child = 2 * i + 1;
        if (child >= heap.size()) break;
        if (child + 1 < heap.size() && before(heap[child], heap[child + 1])) ++child;
        if (!before(x, heap[child])) break;
        heap[i] = heap[child];
        i = child;
    }
    heap[i] = x;
}

}  // namespace

PointKdTree::PointKdTree(std::span<const Point3> points, int threads) {
    static_assert(sizeof(Node) == 16, "a point and its index: four nodes per cache line");
    if (points.size() > kMaxPoints)
        throw Error("point kd-tree: " + std::to_string(points.size()) + " points; at most 2^30 - 1 are supported");
    m_nodes.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Point3& p = points[i];
        if (!is_finite(p)) {
            std::ostringstream message;
            message << "point kd-tree: point " << i << " is (" << p.x << ", " << p.y << ", " << p.z
                    << "); every coordinate must be finite";
            throw Error(message.str());
        }
        m_nodes[i] = {p, static_cast<std::uint32_t>(i) << 2};
        m_bounds.expand(p);
    }
    accel::run_on_threads(threads, [&] { build(m_nodes); });
}

void PointKdTree::build(std::span<Node> nodes) {
    if (nodes.size() <= kLeafSize) {
        std::sort(nodes.begin(), nodes.end(), [](const Node& a, const Node& b) { return a.index() < b.index(); });
        return;
    }
    AABB box;
    for (const Node& n : nodes) box.expand(n.p);
    const int axis = box.longest_axis();
    const std::size_t mid = nodes.size() / 2;
    std::nth_element(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(mid), nodes.end(),
                     [axis](const Node& a, const Node& b) {
                         return a.p[axis] < b.p[axis] || (a.p[axis] == b.p[axis] && a.index() < b.index());
                     });
    nodes[mid].index_axis = (nodes[mid].index_axis & ~3u) | static_cast<std::uint32_t>(axis);
    const std::span<Node> left = nodes.first(mid);
    const std::span<Node> right = nodes.subspan(mid + 1);
    if (nodes.size() >= kParallelPoints)
        tbb::parallel_invoke([left] { build(left); }, [right] { build(right); });
    else {
        build(left);
        build(right);
    }
}

std::size_t PointKdTree::nearest(const Point3& query, float radius2, std::span<PointNeighbor> out) const {
    const std::size_t k = out.size();
    if (k == 0) return 0;
    std::size_t count = 0;
    search(query, radius2, [&](std::uint32_t index, float d2) {
        const PointNeighbor candidate{index, d2};
        if (count < k) {
            out[count++] = candidate;
            std::push_heap(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count), before);
        } else if (before(candidate, out[0])) {
            replace_front(out, candidate);
        }
        return count < k ? radius2 : out[0].distance2;
    });
    std::sort_heap(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count), before);
    return count;
}

void PointKdTree::within(const Point3& query, float radius2, std::vector<PointNeighbor>& out, PointOrder order) const {
    const std::size_t first = out.size();
    for_each_within(query, radius2, [&](std::uint32_t index, float d2) { out.push_back({index, d2}); });
    if (order == PointOrder::index)
        std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
                  [](const PointNeighbor& a, const PointNeighbor& b) { return a.index < b.index; });
}

}  // namespace rtlab
