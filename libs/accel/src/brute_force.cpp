// Every triangle, every ray: the reference the other structures are checked against.
#include "baselines.hpp"
#include "mesh_triangles.hpp"

namespace rtlab::accel {

namespace {

class BruteForce final : public TriangleAccelerator {
public:
    BruteForce(const TriangleMesh& mesh, const BuildOptions& options) : m_triangles(mesh, options.triangle_test) {
        for (std::size_t i = 0; i < m_triangles.size(); ++i)
            if (m_triangles.usable(i)) m_usable.push_back(static_cast<std::uint32_t>(i));
    }
    std::string_view name() const override { return "brute"; }

    bool intersect(const Ray& ray, MeshHit& hit) const override {
        return dispatch_triangle_test(m_triangles.test(), [&]<TriangleTest Test>() {
            const TriangleRay<Test> r(ray);
            float closest = ray.tmax;
            bool any = false;
            for (std::uint32_t i : m_usable) any |= test_triangle<Test>(m_triangles, r, i, closest, hit);
            return any;
        });
    }
    bool occluded(const Ray& ray) const override {
        return dispatch_triangle_test(m_triangles.test(), [&]<TriangleTest Test>() {
            const TriangleRay<Test> r(ray);
            MeshHit ignored;
            for (std::uint32_t i : m_usable) {
                float closest = ray.tmax;
                if (test_triangle<Test>(m_triangles, r, i, closest, ignored)) return true;
            }
            return false;
        });
    }
    AccelStats stats() const override {
        AccelStats s;
        s.bytes = static_cast<std::int64_t>(m_triangles.bytes() + m_usable.size() * 4);
        return s;
    }

private:
    MeshTriangles m_triangles;
    std::vector<std::uint32_t> m_usable;
};

}  // namespace

std::unique_ptr<TriangleAccelerator> make_brute_force(const TriangleMesh& mesh, const BuildOptions& options) {
    return std::make_unique<BruteForce>(mesh, options);
}

}  // namespace rtlab::accel
