// Bounding volume hierarchy, binned SAH (16 bins on the longest centroid axis), flat 32-byte nodes,
// both children's boxes tested and the nearer entered first; leaves address their triangles in a
// leaf-ordered copy.
#include "baselines.hpp"
#include "mesh_triangles.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace rtlab::accel {

namespace {

struct BvhNode {
    AABB box;                       // 24 bytes
    std::uint32_t offset_or_right;  // leaf: first primitive; interior: right child (left is next)
    std::uint16_t count;            // 0 for interior
    std::uint16_t axis;
};
static_assert(sizeof(BvhNode) == 32);

constexpr int kBins = 16;
constexpr std::size_t kMaxLeaf = 4;
// Below this depth the split is a median one, so the depth stays under kMedianDepth + log2(N) and the
// traversal stack (one entry per level) cannot overflow.
constexpr int kMedianDepth = 100;
constexpr int kStackSize = 256;

class Bvh final : public TriangleAccelerator {
public:
    Bvh(const TriangleMesh& mesh, const BuildOptions& options)
        : m_start(std::chrono::steady_clock::now()), m_triangles(mesh, options.triangle_test, build_tree(mesh)) {
        m_stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
        m_stats.nodes = static_cast<std::int64_t>(m_nodes.size());
        m_stats.bytes = static_cast<std::int64_t>(m_nodes.size() * sizeof(BvhNode) + m_triangles.bytes());
        std::int64_t leaves = 0, prims = 0;
        double cost = 0.0;
        const float root_area = m_nodes.empty() ? 1.0f : m_nodes[0].box.surface_area();
        for (const auto& n : m_nodes) {
            const double p = root_area > 0 ? n.box.surface_area() / root_area : 0.0;
            if (n.count > 0)
                ++leaves, prims += n.count, cost += p * 1.5 * n.count;
            else
                cost += p * 1.0;
        }
        m_stats.leaves = leaves;
        m_stats.empty_leaves = 0;
        m_stats.max_depth = m_depth;
        m_stats.mean_leaf_primitives = leaves ? static_cast<double>(prims) / leaves : 0.0;
        m_stats.sah_cost = cost;
    }

    std::string_view name() const override { return "bvh"; }
    bool intersect(const Ray& ray, MeshHit& hit) const override { return traverse<false>(ray, hit); }
    bool occluded(const Ray& ray) const override {
        MeshHit ignored;
        return traverse<true>(ray, ignored);
    }
    AccelStats stats() const override { return m_stats; }

private:
    // Builds the nodes and returns the leaves' triangles in leaf order (the layout of m_triangles, so a
    // leaf's triangles are adjacent in memory and a leaf addresses them by position).
    std::vector<std::uint32_t> build_tree(const TriangleMesh& mesh) {
        std::vector<Item> items;
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
            if (mesh.is_degenerate(i)) continue;
            const AABB b = mesh.triangle_bounds(i);
            items.push_back({static_cast<std::uint32_t>(i), b, b.center()});
        }
        if (!items.empty()) build(items, 0, items.size(), 0);
        return std::move(m_prims);
    }

    struct Item {
        std::uint32_t index;
        AABB box;
        Point3 centre;
    };

    std::uint32_t build(std::vector<Item>& items, std::size_t first, std::size_t last, int depth) {
        m_depth = std::max<std::int64_t>(m_depth, depth);
        const auto index = static_cast<std::uint32_t>(m_nodes.size());
        m_nodes.push_back({});
        AABB box, centres;
        for (std::size_t i = first; i < last; ++i) {
            box.expand(items[i].box);
            centres.expand(items[i].centre);
        }
        m_nodes[index].box = box;
        const std::size_t n = last - first;
        auto make_leaf = [&] {
            m_nodes[index].offset_or_right = static_cast<std::uint32_t>(m_prims.size());
            m_nodes[index].count = static_cast<std::uint16_t>(n);
            for (std::size_t i = first; i < last; ++i) m_prims.push_back(items[i].index);
            return index;
        };
        const int axis = centres.longest_axis();
        const float lo = centres.lo[axis], extent = centres.hi[axis] - lo;
        if ((n <= kMaxLeaf || !(extent > 0.0f)) && n <= 65535) return make_leaf();
        if (!(extent > 0.0f)) {  // more coincident centres than a leaf holds: halve the list
            const std::size_t mid = first + n / 2;
            m_nodes[index].axis = static_cast<std::uint16_t>(axis);
            build(items, first, mid, depth + 1);
            m_nodes[index].offset_or_right = build(items, mid, last, depth + 1);
            return index;
        }
        std::array<AABB, kBins> bin_box{};
        std::array<std::size_t, kBins> bin_count{};
        auto bin_of = [&](const Item& it) {
            return std::clamp(static_cast<int>((it.centre[axis] - lo) / extent * kBins), 0, kBins - 1);
        };
        for (std::size_t i = first; i < last; ++i) {
            const int b = bin_of(items[i]);
            ++bin_count[b];
            bin_box[b].expand(items[i].box);
        }
        std::array<float, kBins> right_area{};
        AABB acc;
        std::size_t acc_n = 0;
        std::array<std::size_t, kBins> right_n{};
        for (int b = kBins - 1; b > 0; --b) {
            acc.expand(bin_box[b]);
            acc_n += bin_count[b];
            right_area[b] = acc.surface_area();
            right_n[b] = acc_n;
        }
        float best_cost = 1.5f * static_cast<float>(n);
        int best_split = -1;
        AABB left;
        std::size_t left_n = 0;
        const float inv_area = 1.0f / std::max(box.surface_area(), 1e-30f);
        for (int b = 1; b < kBins; ++b) {
            left.expand(bin_box[b - 1]);
            left_n += bin_count[b - 1];
            if (left_n == 0 || right_n[b] == 0) continue;
            const float cost = 1.0f + 1.5f * inv_area * (left.surface_area() * left_n + right_area[b] * right_n[b]);
            if (cost < best_cost) best_cost = cost, best_split = b;
        }
        if (depth >= kMedianDepth)
            best_split = -1;
        else if (best_split < 0 && n <= 65535)
            return make_leaf();
        std::size_t mid;
        if (best_split < 0) {
            mid = first + n / 2;
            std::nth_element(items.begin() + first, items.begin() + mid, items.begin() + last,
                             [&](const Item& a, const Item& b) { return a.centre[axis] < b.centre[axis]; });
        } else {
            mid = static_cast<std::size_t>(std::partition(items.begin() + first, items.begin() + last,
                                                          [&](const Item& it) { return bin_of(it) < best_split; }) -
                                           items.begin());
        }
        m_nodes[index].axis = static_cast<std::uint16_t>(axis);
        build(items, first, mid, depth + 1);
        const std::uint32_t right = build(items, mid, last, depth + 1);
        m_nodes[index].offset_or_right = right;
        return index;
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
            Entry stack[kStackSize];
            int top = 0;
            const float root_t = box_ray.enter(m_nodes[0].box, closest);
            if (root_t == kInfinity) return false;
            stack[top++] = {0, root_t};
            while (top > 0) {
                const Entry e = stack[--top];
                if (e.t > BoxRay::enlarge(closest)) continue;  // a closer hit was found since it was pushed
                std::uint32_t index = e.node;
                for (;;) {
                    const BvhNode& node = m_nodes[index];
                    if (node.count > 0) {
                        if (test_leaf<Test, AnyHit>(m_triangles, r, node.offset_or_right, node.count, closest, hit)) {
                            any = true;
                            if constexpr (AnyHit) return true;
                        }
                        break;
                    }
                    const std::uint32_t left = index + 1, right = node.offset_or_right;
                    const float tl = box_ray.enter(m_nodes[left].box, closest);
                    const float tr = box_ray.enter(m_nodes[right].box, closest);
                    if (tl == kInfinity && tr == kInfinity) break;
                    if (tl == kInfinity) {
                        index = right;
                        continue;
                    }
                    if (tr == kInfinity) {
                        index = left;
                        continue;
                    }
                    // Both: descend into the nearer, keep the farther for later.
                    if (tl <= tr) {
                        stack[top++] = {right, tr};
                        index = left;
                    } else {
                        stack[top++] = {left, tl};
                        index = right;
                    }
                }
            }
            return any;
        });
    }

    // Declared before m_triangles: build_tree fills them while m_triangles is being initialised.
    std::chrono::steady_clock::time_point m_start;
    std::vector<BvhNode> m_nodes;
    std::vector<std::uint32_t> m_prims;  // only during the build
    std::int64_t m_depth = 0;
    MeshTriangles m_triangles;
    AccelStats m_stats;
};

}  // namespace

std::unique_ptr<TriangleAccelerator> make_bvh(const TriangleMesh& mesh, const BuildOptions& options) {
    return std::make_unique<Bvh>(mesh, options);
}

}  // namespace rtlab::accel
