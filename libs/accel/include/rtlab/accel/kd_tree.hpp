#pragma once
/// \brief kd-trees: generic over any primitive source, over shapes (a tree of trees), and over meshes.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/kd_build.hpp>
#include <rtlab/accel/kd_traverse.hpp>
#include <rtlab/geometry/shape.hpp>

#include <concepts>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// \brief What a kd-tree can index: a count, bounds of primitive i, closest-hit and any-hit tests of
/// primitive i. `Hit` has a member `t`; intersect(i, ray, hit) accepts only tmin < t < ray.tmax and
/// fills hit. Optionally clipped_bounds(i, box) gives the bounds of the part inside box (perfect splits).
template <class S>
concept KdPrimitiveSource = requires(const S& s, std::uint32_t i, const Ray& ray, typename S::Hit& hit) {
    { s.size() } -> std::convertible_to<std::size_t>;
    { s.bounds(i) } -> std::convertible_to<AABB>;
    { s.intersect(i, ray, hit) } -> std::same_as<bool>;
    { s.occluded(i, ray) } -> std::same_as<bool>;
    { hit.t } -> std::convertible_to<float>;
};

template <class S>
concept KdClippableSource = requires(const S& s, std::uint32_t i, const AABB& box) {
    { s.clipped_bounds(i, box) } -> std::convertible_to<AABB>;
};

/// \brief A kd-tree over any primitive source.
template <KdPrimitiveSource Source>
class KdTree {
public:
    using Hit = typename Source::Hit;

    KdTree(Source source, KdStrategy strategy, const KdCostModel& cost = {}, int threads = 0)
        : m_source(std::move(source)) {
        KdBuildInput input;
        input.bounds.reserve(m_source.size());
        for (std::size_t i = 0; i < m_source.size(); ++i)
            input.bounds.push_back(m_source.bounds(static_cast<std::uint32_t>(i)));
        if constexpr (KdClippableSource<Source>)
            input.clip = [this](std::uint32_t i, const AABB& box) { return m_source.clipped_bounds(i, box); };
        m_tree = build_kd_tree(input, strategy, cost, threads);
    }

    /// Closest hit with ray.tmin < t < ray.tmax; fills hit and returns true on a hit.
    bool intersect(const Ray& ray, Hit& hit) const {
        return kd_traverse<false>(m_tree, ray, [&](const KdNode& leaf, float& closest) {
            bool any = false;
            for_each_primitive(leaf, [&](std::uint32_t i) {
                Ray clipped = ray;
                clipped.tmax = closest;
                if (!m_source.intersect(i, clipped, hit)) return false;
                closest = hit.t;
                any = true;
                return false;
            });
            return any;
        });
    }
    bool occluded(const Ray& ray) const {
        return kd_traverse<true>(m_tree, ray, [&](const KdNode& leaf, float&) {
            return for_each_primitive(leaf, [&](std::uint32_t i) { return m_source.occluded(i, ray); });
        });
    }

    const KdTreeData& data() const { return m_tree; }
    const Source& source() const { return m_source; }

private:
    // Calls f(primitive) for each primitive of a leaf until f returns true; returns whether one did.
    template <class F>
    bool for_each_primitive(const KdNode& leaf, F&& f) const {
        const std::uint32_t count = leaf.primitive_count();
        if (count == 1) return f(leaf.primitive_offset());
        const std::uint32_t* primitives = m_tree.primitive_indices.data() + leaf.primitive_offset();
        for (std::uint32_t k = 0; k < count; ++k)
            if (f(primitives[k])) return true;
        return false;
    }

    Source m_source;
    KdTreeData m_tree;
};

/// \brief Shapes of any kind as kd-tree primitives.
struct ShapeSource {
    using Hit = SurfaceHit;
    std::vector<std::shared_ptr<const Shape>> shapes;

    std::size_t size() const { return shapes.size(); }
    AABB bounds(std::uint32_t i) const { return shapes[i]->bounds(); }
    bool intersect(std::uint32_t i, const Ray& ray, SurfaceHit& hit) const { return shapes[i]->intersect(ray, hit); }
    bool occluded(std::uint32_t i, const Ray& ray) const { return shapes[i]->occluded(ray); }
};

/// \brief A kd-tree over shapes that is itself a Shape: a scene's objects, or a tree of mesh trees.
class KdShapeTree final : public Shape {
public:
    explicit KdShapeTree(std::vector<std::shared_ptr<const Shape>> shapes, KdStrategy strategy = KdStrategy::sah)
        : m_tree(ShapeSource{std::move(shapes)}, strategy) {}

    AABB bounds() const override { return m_tree.data().bounds; }
    bool intersect(const Ray& ray, SurfaceHit& hit) const override { return m_tree.intersect(ray, hit); }
    bool occluded(const Ray& ray) const override { return m_tree.occluded(ray); }
    const KdTreeData& data() const { return m_tree.data(); }

private:
    KdTree<ShapeSource> m_tree;
};

/// The kd-tree methods make_kd_tree knows: kd-sah, kd-sah-binned, kd-sah-naive, kd-median, kd-midpoint.
std::vector<std::string> kd_tree_methods();

/// The leaf widths (triangles tested at once) this CPU runs, widest last: {4}, or {4, 8} with AVX2.
std::vector<int> kd_leaf_widths();

/// A kd-tree over a mesh's triangles with a leaf layout precomputed for options.triangle_test, in packets
/// of options.leaf_width triangles. Throws rtlab::Error for a width the CPU does not run.
/// Degenerate triangles are left out (they are never hit).
std::unique_ptr<TriangleAccelerator> make_kd_tree(std::string_view method, const TriangleMesh& mesh,
                                                  const BuildOptions& options = {});
/// The same with a cost model of one's own (the SAH strategies read it).
std::unique_ptr<TriangleAccelerator> make_kd_tree(std::string_view method, const TriangleMesh& mesh,
                                                  const BuildOptions& options, const KdCostModel& cost);

/// The cost model of make_kd_tree: leaves are tested four or eight triangles at a time, so a triangle costs
/// well under a tenth of a traversal step. With 8-wide leaves (bunny, dragon, armadillo, buddha, teapot;
/// random rays, 1 thread, trees interleaved in one process) 0.07 beat 0.1 on any-hit by 2-5% and was
/// within 3% either way on closest-hit; 0.05 was no better, 0.035 and 0.15 were slower, and 0.3, right for
/// one triangle at a time, is 10-20% slower. The empty bonus 0.2 against 0.0, 0.5 and 0.8 (bunny, random
/// rays, 1 thread, both trees in one process): 0.81-0.87x, 0.93-0.95x and 0.93-0.96x closest-hit, 0.87-0.89x,
/// 0.92x and 0.93x any-hit.
inline KdCostModel kd_mesh_cost_model() { return KdCostModel(1.0f, 0.07f, 0.2f); }

}  // namespace rtlab
