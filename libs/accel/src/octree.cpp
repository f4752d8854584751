// Octree: each node split into eight equal children, a leaf at <= 10 primitives or depth 10; children
// visited in order of where the ray enters them.
#include "baselines.hpp"
#include "mesh_triangles.hpp"

#include <algorithm>
#include <array>
#include <chrono>

namespace rtlab::accel {

namespace {

constexpr std::size_t kLeafSize = 10;
constexpr int kMaxDepth = 10;

struct OctNode {
    AABB box;
    std::uint32_t first;  // interior: first of 8 consecutive children; leaf: offset into m_triangles
    std::uint32_t count;  // leaf primitive count; kInterior for interior nodes
};
constexpr std::uint32_t kInterior = 0xFFFFFFFFu;

class Octree final : public TriangleAccelerator {
public:
    Octree(const TriangleMesh& mesh, const BuildOptions& options)
        : m_start(std::chrono::steady_clock::now()), m_triangles(mesh, options.triangle_test, build_tree(mesh)) {
        m_stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
        std::int64_t leaves = 0, empty = 0, prims = 0;
        for (const auto& n : m_nodes)
            if (n.count != kInterior) ++leaves, empty += n.count == 0, prims += n.count;
        m_stats.nodes = static_cast<std::int64_t>(m_nodes.size());
        m_stats.leaves = leaves;
        m_stats.empty_leaves = empty;
        m_stats.max_depth = m_depth;
        m_stats.mean_leaf_primitives =
            leaves > empty ? static_cast<double>(prims) / static_cast<double>(leaves - empty) : 0.0;
        m_stats.bytes = static_cast<std::int64_t>(m_nodes.size() * sizeof(OctNode) + m_triangles.bytes());
    }

    std::string_view name() const override { return "octree"; }
    bool intersect(const Ray& ray, MeshHit& hit) const override { return traverse<false>(ray, hit); }
    bool occluded(const Ray& ray) const override {
        MeshHit ignored;
        return traverse<true>(ray, ignored);
    }
    AccelStats stats() const override { return m_stats; }

private:
    // Builds the nodes and returns the leaves' triangle references in leaf order: m_triangles holds one
    // copy per reference, so a leaf's triangles are adjacent in memory and addressed by position.
    std::vector<std::uint32_t> build_tree(const TriangleMesh& mesh) {
        std::vector<std::uint32_t> all;
        AABB box;
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
            if (mesh.is_degenerate(i)) continue;
            all.push_back(static_cast<std::uint32_t>(i));
            box.expand(mesh.triangle_bounds(i));
        }
        m_nodes.push_back({box, 0, 0});
        if (!all.empty()) build(mesh, 0, all, 0);
        return std::move(m_prims);
    }

    void build(const TriangleMesh& mesh, std::uint32_t index, const std::vector<std::uint32_t>& prims, int depth) {
        m_depth = std::max<std::int64_t>(m_depth, depth);
        if (prims.size() <= kLeafSize || depth >= kMaxDepth) {
            m_nodes[index].first = static_cast<std::uint32_t>(m_prims.size());
            m_nodes[index].count = static_cast<std::uint32_t>(prims.size());
            m_prims.insert(m_prims.end(), prims.begin(), prims.end());
            return;
        }
        const AABB box = m_nodes[index].box;
        const Point3 mid = box.center();
        std::array<AABB, 8> child_box;
        std::array<std::vector<std::uint32_t>, 8> inside;
        std::size_t references = 0;
        for (int c = 0; c < 8; ++c) {
            for (int a = 0; a < 3; ++a) {
                const bool upper = (c >> a) & 1;
                child_box[c].lo[a] = upper ? mid[a] : box.lo[a];
                child_box[c].hi[a] = upper ? box.hi[a] : mid[a];
            }
            // On an axis where the node is flat both halves are the same slab: only the lower one is filled.
            bool duplicate_half = false;
            for (int a = 0; a < 3; ++a) duplicate_half |= ((c >> a) & 1) && !(box.hi[a] > box.lo[a]);
            if (duplicate_half) continue;
            for (std::uint32_t p : prims) {
                // Clip only triangles whose bounds cross the child's border; most are wholly in or out.
                const AABB b = mesh.triangle_bounds(p);
                if (b.intersected(child_box[c]).is_empty()) continue;
                const bool contained = child_box[c].contains(b.lo) && child_box[c].contains(b.hi);
                if (contained ||
                    !clip_triangle(mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2), child_box[c]).is_empty())
                    inside[c].push_back(p);
            }
            references += inside[c].size();
        }
        // Children that would together hold more than 3 copies of every primitive (a flat node, or
        // heavily overlapping primitives such as stacked quads) do not pay: this node stays a leaf,
        // which also keeps the tree from growing exponentially.
        if (references > 3 * prims.size()) {
            m_nodes[index].first = static_cast<std::uint32_t>(m_prims.size());
            m_nodes[index].count = static_cast<std::uint32_t>(prims.size());
            m_prims.insert(m_prims.end(), prims.begin(), prims.end());
            return;
        }
        const auto first = static_cast<std::uint32_t>(m_nodes.size());
        m_nodes[index].first = first;
        m_nodes[index].count = kInterior;
        for (int c = 0; c < 8; ++c) m_nodes.push_back({child_box[c], 0, 0});
        for (int c = 0; c < 8; ++c) build(mesh, first + static_cast<std::uint32_t>(c), inside[c], depth + 1);
    }

    template <bool AnyHit>
    bool traverse(const Ray& ray, MeshHit& hit) const {
        return dispatch_triangle_test(m_triangles.test(), [&]<TriangleTest Test>() {
            const TriangleRay<Test> r(ray);
            float closest = ray.tmax;
            bool any = false;
            struct Entry {
                std::uint32_t node;
                float tmin;
            };
            Entry stack[8 * (kMaxDepth + 1)];
            int top = 0;
            if (!usable_ray(ray)) return false;
            const BoxRay box_ray(ray);
            const float root_t = box_ray.enter(m_nodes[0].box, closest);
            if (root_t != kInfinity) stack[top++] = {0, root_t};
            while (top > 0) {
                const Entry e = stack[--top];
                if (e.tmin > BoxRay::enlarge(closest)) continue;  // a closer hit was found since it was pushed
                const OctNode& node = m_nodes[e.node];
                if (node.count != kInterior) {
                    if (test_leaf<Test, AnyHit>(m_triangles, r, node.first, node.count, closest, hit)) {
                        any = true;
                        if constexpr (AnyHit) return true;
                    }
                    continue;
                }
                // Push the children the ray enters, farthest first, so the nearest is popped next.
                std::array<Entry, 8> children;
                int n = 0;
                for (std::uint32_t c = 0; c < 8; ++c) {
                    const float t = box_ray.enter(m_nodes[node.first + c].box, closest);
                    if (t != kInfinity) children[n++] = {node.first + c, t};
                }
                for (int k = 1; k < n; ++k)  // insertion sort, farthest first: at most 8 entries
                    for (int m = k; m > 0 && children[m - 1].tmin < children[m].tmin; --m)
                        std::swap(children[m - 1], children[m]);
                for (int k = 0; k < n; ++k) stack[top++] = children[k];
            }
            return any;
        });
    }

    // Declared before m_triangles: build_tree fills them while m_triangles is being initialised.
    std::chrono::steady_clock::time_point m_start;
    std::vector<OctNode> m_nodes;
    std::vector<std::uint32_t> m_prims;  // only during the build
    std::int64_t m_depth = 0;
    MeshTriangles m_triangles;
    AccelStats m_stats;
};

}  // namespace

std::unique_ptr<TriangleAccelerator> make_octree(const TriangleMesh& mesh, const BuildOptions& options) {
    return std::make_unique<Octree>(mesh, options);
}

}  // namespace rtlab::accel
