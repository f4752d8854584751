// Bounding volume hierarchy, binned SAH (16 bins on the longest centroid axis), flat 32-byte nodes,
// children visited near-first by the ray's direction sign on the split axis.
#include "baselines.hpp"
#include "mesh_triangles.hpp"

#include <algorithm>
#include <array>
#include <chrono>

namespace rtlab::accel {

namespace {

struct BvhNode {
    AABB box;                     // 24 bytes
    std::uint32_t offset_or_right;  // leaf: first primitive; interior: right child (left is next)
    std::uint16_t count;          // 0 for interior
    std::uint16_t axis;
};
static_assert(sizeof(BvhNode) == 32);

constexpr int kBins = 16;
constexpr std::size_t kMaxLeaf = 4;

class Bvh final : public TriangleAccelerator {
public:
    Bvh(const TriangleMesh& mesh, const BuildOptions& options) : m_triangles(mesh, options.triangle_test) {
        const auto start = std::chrono::steady_clock::now();
        std::vector<Item> items;
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
            if (!m_triangles.usable(i)) continue;
            const AABB b = mesh.triangle_bounds(i);
            items.push_back({static_cast<std::uint32_t>(i), b, b.center()});
        }
        if (!items.empty()) build(items, 0, items.size(), 0);
        m_stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        m_stats.nodes = static_cast<std::int64_t>(m_nodes.size());
        m_stats.bytes = static_cast<std::int64_t>(m_nodes.size() * sizeof(BvhNode) + m_prims.size() * 4 + m_triangles.bytes());
        std::int64_t leaves = 0, prims = 0;
        double cost = 0.0;
        const float root_area = m_nodes.empty() ? 1.0f : m_nodes[0].box.surface_area();
        for (const auto& n : m_nodes) {
            const double p = root_area > 0 ? n.box.surface_area() / root_area : 0.0;
            if (n.count > 0) ++leaves, prims += n.count, cost += p * 1.5 * n.count;
            else cost += p * 1.0;
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
        if (best_split < 0 && n <= 65535) return make_leaf();
        std::size_t mid;
        if (best_split < 0) {
            mid = first + n / 2;
            std::nth_element(items.begin() + first, items.begin() + mid, items.begin() + last,
                             [&](const Item& a, const Item& b) { return a.centre[axis] < b.centre[axis]; });
        } else {
            mid = static_cast<std::size_t>(
                std::partition(items.begin() + first, items.begin() + last, [&](const Item& it) { return bin_of(it) < best_split; }) -
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
        if (m_nodes.empty()) return false;
        return dispatch_triangle_test(m_triangles.test(), [&]<TriangleTest Test>() {
            const TriangleRay<Test> r(ray);
            float closest = ray.tmax;
            bool any = false;
            std::uint32_t stack[128];
            int top = 0;
            stack[top++] = 0;
            while (top > 0) {
                const BvhNode& node = m_nodes[stack[--top]];
                Ray clipped = ray;
                clipped.tmax = closest;
                if (!node.box.intersect(clipped)) continue;
                if (node.count > 0) {
                    for (std::uint32_t k = 0; k < node.count; ++k) {
                        if (test_triangle<Test>(m_triangles, r, m_prims[node.offset_or_right + k], closest, hit)) {
                            any = true;
                            if constexpr (AnyHit) return true;
                        }
                    }
                    continue;
                }
                const auto self = static_cast<std::uint32_t>(&node - m_nodes.data());
                const std::uint32_t left = self + 1, right = node.offset_or_right;
                if (ray.direction[node.axis] > 0.0f) {
                    stack[top++] = right;
                    stack[top++] = left;
                } else {
                    stack[top++] = left;
                    stack[top++] = right;
                }
            }
            return any;
        });
    }

    MeshTriangles m_triangles;
    std::vector<BvhNode> m_nodes;
    std::vector<std::uint32_t> m_prims;
    AccelStats m_stats;
    std::int64_t m_depth = 0;
};

}  // namespace

std::unique_ptr<TriangleAccelerator> make_bvh(const TriangleMesh& mesh, const BuildOptions& options) {
    return std::make_unique<Bvh>(mesh, options);
}

}  // namespace rtlab::accel
