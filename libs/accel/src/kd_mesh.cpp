// kd-trees over a mesh's triangles: the shared builder with perfect splits (triangles clipped to the
// node box), and the shared traversal with the leaf test of the chosen triangle method.
#include <rtlab/accel/kd_tree.hpp>

#include "mesh_triangles.hpp"

namespace rtlab {

namespace {

class KdMeshAccelerator final : public TriangleAccelerator {
public:
    KdMeshAccelerator(KdStrategy strategy, const TriangleMesh& mesh, const BuildOptions& options)
        : m_name(kd_strategy_name(strategy)), m_triangles(mesh, options.triangle_test) {
        KdBuildInput input;
        input.bounds.reserve(mesh.triangle_count());
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i)
            input.bounds.push_back(m_triangles.usable(i) ? mesh.triangle_bounds(i) : AABB{});
        input.clip = [&mesh](std::uint32_t i, const AABB& box) {
            return accel::clip_triangle(mesh.corner(i, 0), mesh.corner(i, 1), mesh.corner(i, 2), box);
        };
        m_tree = build_kd_tree(input, strategy, KdCostModel{}, options.threads);
        m_tree.stats.bytes += static_cast<std::int64_t>(m_triangles.bytes());
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
    std::string m_name;
    accel::MeshTriangles m_triangles;
    KdTreeData m_tree;
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
