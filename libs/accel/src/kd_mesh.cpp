// kd-trees over a mesh's triangles: the shared builder with perfect splits (triangles clipped to the
// node box), and the shared traversal with the leaf test of the chosen triangle method.
#include <rtlab/accel/kd_tree.hpp>

#include "mesh_triangles.hpp"

namespace rtlab {

namespace {

class KdMeshAccelerator final : public TriangleAccelerator {
public:
    KdMeshAccelerator(KdStrategy strategy, const TriangleMesh& mesh, const BuildOptions& options)
        : m_name(kd_strategy_name(strategy)), m_tree(build(strategy, mesh, options)),
          m_triangles(mesh, options.triangle_test, leaf_order(m_tree)) {
        m_tree.stats.bytes = static_cast<std::int64_t>(m_tree.nodes.size() * sizeof(KdNode) +
                                                       m_tree.primitive_indices.size() * sizeof(std::uint32_t) +
                                                       m_triangles.bytes());
    }

    std::string_view name() const override { return m_name; }

    bool intersect(const Ray& ray, MeshHit& hit) const override {
        return accel::dispatch_triangle_test(m_triangles.test(), [&]<TriangleTest Test>() {
            const accel::TriangleRay<Test> r(ray);
            return kd_traverse<false>(m_tree, ray, [&](std::uint32_t i, float& closest) {
                return accel::test_triangle<Test>(m_triangles, r, i, closest, hit);
            });
        });
    }

    bool occluded(const Ray& ray) const override {
        return accel::dispatch_triangle_test(m_triangles.test(), [&]<TriangleTest Test>() {
            const accel::TriangleRay<Test> r(ray);
            MeshHit ignored;
            return kd_traverse<true>(m_tree, ray, [&](std::uint32_t i, float& closest) {
                return accel::test_triangle<Test>(m_triangles, r, i, closest, ignored);
            });
        });
    }

    AccelStats stats() const override { return m_tree.stats; }

private:
    static KdTreeData build(KdStrategy strategy, const TriangleMesh& mesh, const BuildOptions& options) {
        KdBuildInput input;
        input.bounds.reserve(mesh.triangle_count());
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i)
            input.bounds.push_back(mesh.is_degenerate(i) ? AABB{} : mesh.triangle_bounds(i));
        input.clip = [&mesh](std::uint32_t i, const AABB& box) {
            return accel::clip_triangle(mesh.corner(i, 0), mesh.corner(i, 1), mesh.corner(i, 2), box);
        };
        return build_kd_tree(input, strategy, KdCostModel{}, options.threads);
    }

    // Renumbers the leaves so that every leaf (one-primitive leaves too) refers to consecutive entries of
    // the leaf-ordered triangle array; returns the mesh triangle of each entry.
    static std::vector<std::uint32_t> leaf_order(KdTreeData& tree) {
        std::vector<std::uint32_t> order;
        order.reserve(tree.primitive_indices.size() + tree.nodes.size() / 2);
        for (KdNode& node : tree.nodes) {
            if (!node.is_leaf()) continue;
            const std::uint32_t count = node.primitive_count();
            const auto first = static_cast<std::uint32_t>(order.size());
            if (count == 1) order.push_back(node.primitive_offset());
            for (std::uint32_t k = 0; count > 1 && k < count; ++k)
                order.push_back(tree.primitive_indices[node.primitive_offset() + k]);
            // One-primitive leaves name their entry directly; the others go through the identity array.
            node = KdNode::leaf(count, first);
        }
        tree.primitive_indices.resize(order.size());
        for (std::size_t k = 0; k < order.size(); ++k) tree.primitive_indices[k] = static_cast<std::uint32_t>(k);
        return order;
    }

    std::string m_name;
    KdTreeData m_tree;
    accel::MeshTriangles m_triangles;
};

}  // namespace

std::vector<std::string> kd_tree_methods() {
    return {"kd-sah", "kd-sah-binned", "kd-sah-naive", "kd-median", "kd-midpoint"};
}

std::unique_ptr<TriangleAccelerator> make_kd_tree(std::string_view method, const TriangleMesh& mesh,
                                                  const BuildOptions& options) {
    return std::make_unique<KdMeshAccelerator>(parse_kd_strategy(method), mesh, options);
}

}  // namespace rtlab
