// kd-three-way: the course's flat tree. Each node splits its primitives by one plane into those wholly
// below, those wholly above and those straddling it (the middle child), so no primitive is ever copied;
// the plane is the one of 15 evenly spaced candidates on the longest axis that minimises
// |below - above| + 0.5 middle. Children are bounded by their primitives' boxes and visited nearest first.
// Kept for comparison with the SAH trees, not for speed.
#include "baselines.hpp"
#include "mesh_triangles.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace rtlab::accel {

namespace {

constexpr std::size_t kLeafSize = 8;
constexpr int kMaxDepth = 40;
constexpr int kCandidates = 15;

struct ThreeWayNode {
    AABB box;
    std::uint32_t first;  // leaf: first entry of the leaf-ordered triangles; interior: first child
    std::uint32_t count;  // leaf: triangles; interior: 0
    std::uint8_t children = 0;
};

class ThreeWayTree final : public TriangleAccelerator {
public:
    ThreeWayTree(const TriangleMesh& mesh, const BuildOptions& options)
        : m_triangles(mesh, options.triangle_test, build_tree(mesh)) {
        finish_stats();
    }

    std::string_view name() const override { return "kd-three-way"; }
    bool intersect(const Ray& ray, MeshHit& hit) const override { return traverse<false>(ray, hit); }
    bool occluded(const Ray& ray) const override {
        MeshHit ignored;
        return traverse<true>(ray, ignored);
    }
    AccelStats stats() const override { return m_stats; }

private:
    struct Item {
        std::uint32_t index;
        AABB box;
    };

    // Builds the nodes (members declared before m_triangles) and returns the triangles in leaf order.
    std::vector<std::uint32_t> build_tree(const TriangleMesh& mesh) {
        const auto start = std::chrono::steady_clock::now();
        std::vector<Item> items;
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i)
            if (!mesh.is_degenerate(i)) items.push_back({static_cast<std::uint32_t>(i), mesh.triangle_bounds(i)});
        std::vector<std::uint32_t> order;
        m_nodes.push_back({});
        build_node(0, items, order, 0);
        m_stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return order;
    }

    void build_node(std::uint32_t index, std::vector<Item>& items, std::vector<std::uint32_t>& order, int depth) {
        m_depth = std::max<std::int64_t>(m_depth, depth);
        AABB box;
        for (const Item& it : items) box.expand(it.box);
        m_nodes[index].box = box;
        auto make_leaf = [&] {
            m_nodes[index].first = static_cast<std::uint32_t>(order.size());
            m_nodes[index].count = static_cast<std::uint32_t>(items.size());
            for (const Item& it : items) order.push_back(it.index);
        };
        if (items.size() <= kLeafSize || depth >= kMaxDepth) return make_leaf();
        const int axis = box.longest_axis();
        const float lo = box.lo[axis], extent = box.hi[axis] - box.lo[axis];
        if (!(extent > 0.0f)) return make_leaf();
        float best_score = kInfinity, best_plane = 0.0f;
        for (int k = 1; k <= kCandidates; ++k) {
            const float plane = lo + extent * static_cast<float>(k) / (kCandidates + 1);
            std::size_t below = 0, above = 0;
            for (const Item& it : items) {
                below += it.box.hi[axis] < plane;
                above += it.box.lo[axis] > plane;
            }
            const std::size_t middle = items.size() - below - above;
            const float score =
                std::abs(static_cast<float>(below) - static_cast<float>(above)) + 0.5f * static_cast<float>(middle);
            if (score < best_score) best_score = score, best_plane = plane;
        }
        std::array<std::vector<Item>, 3> groups;
        for (const Item& it : items)
            groups[it.box.hi[axis] < best_plane ? 0 : it.box.lo[axis] > best_plane ? 2 : 1].push_back(it);
        // Everything in one group is no progress: a leaf.
        for (const auto& g : groups)
            if (g.size() == items.size()) return make_leaf();
        std::vector<Item>().swap(items);
        const auto first = static_cast<std::uint32_t>(m_nodes.size());
        std::uint8_t children = 0;
        for (const auto& g : groups) children += !g.empty();
        m_nodes[index].first = first;
        m_nodes[index].count = 0;
        m_nodes[index].children = children;
        for (std::uint8_t c = 0; c < children; ++c) m_nodes.push_back({});
        std::uint32_t child = first;
        for (auto& g : groups)
            if (!g.empty()) build_node(child++, g, order, depth + 1);
    }

    void finish_stats() {
        std::int64_t leaves = 0, prims = 0;
        for (const auto& n : m_nodes)
            if (n.children == 0) ++leaves, prims += n.count;
        m_stats.nodes = static_cast<std::int64_t>(m_nodes.size());
        m_stats.leaves = leaves;
        m_stats.empty_leaves = 0;
        m_stats.max_depth = m_depth;
        m_stats.mean_leaf_primitives = leaves ? static_cast<double>(prims) / static_cast<double>(leaves) : 0.0;
        m_stats.bytes = static_cast<std::int64_t>(m_nodes.size() * sizeof(ThreeWayNode) + m_triangles.bytes());
    }

    template <bool AnyHit>
    bool traverse(const Ray& ray, MeshHit& hit) const {
        if (m_nodes.empty() || !usable_ray(ray)) return false;
        return dispatch_triangle_test(m_triangles.test(), [&]<TriangleTest Test>() {
            const TriangleRay<Test> r(ray);
            const BoxRay box_ray(ray);
            float closest = ray.tmax;
            bool any = false;
            struct Entry {
                std::uint32_t node;
                float t;
            };
            Entry stack[3 * (kMaxDepth + 2)];
            int top = 0;
            const float t_root = box_ray.enter(m_nodes[0].box, closest);
            if (t_root != kInfinity) stack[top++] = {0, t_root};
            while (top > 0) {
                const Entry e = stack[--top];
                if (e.t > BoxRay::enlarge(closest)) continue;  // a closer hit was found since it was pushed
                const ThreeWayNode& node = m_nodes[e.node];
                if (node.children == 0) {
                    if (test_leaf<Test, AnyHit>(m_triangles, r, node.first, node.count, closest, hit)) {
                        any = true;
                        if constexpr (AnyHit) return true;
                    }
                    continue;
                }
                // Push the children the ray enters, farthest first, so the nearest is popped next.
                Entry children[3];
                int n = 0;
                for (std::uint32_t c = 0; c < node.children; ++c) {
                    const float t = box_ray.enter(m_nodes[node.first + c].box, closest);
                    if (t != kInfinity) children[n++] = {node.first + c, t};
                }
                for (int k = 1; k < n; ++k)
                    for (int m = k; m > 0 && children[m - 1].t < children[m].t; --m)
                        std::swap(children[m - 1], children[m]);
                for (int k = 0; k < n; ++k) stack[top++] = children[k];
            }
            return any;
        });
    }

    std::vector<ThreeWayNode> m_nodes;
    std::int64_t m_depth = 0;
    AccelStats m_stats;
    MeshTriangles m_triangles;
};

}  // namespace

std::unique_ptr<TriangleAccelerator> make_kd_three_way(const TriangleMesh& mesh, const BuildOptions& options) {
    return std::make_unique<ThreeWayTree>(mesh, options);
}

}  // namespace rtlab::accel
