// kd-trees over a mesh's triangles: the shared builder with perfect splits (triangles clipped to the
// node box), and the shared traversal with leaves tested four triangles at a time by the chosen method.
#include <rtlab/accel/kd_build.hpp>
#include <rtlab/accel/kd_tree.hpp>

#include "kd_packet_walk.hpp"
#include "kd_packets.hpp"
#include "mesh_triangles.hpp"
#include "thread_arena.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <span>
#include <string>

namespace rtlab {

namespace {

bool cpu_has_avx2() {
#if RTLAB_KD_HAVE_AVX2_LEAVES
    __builtin_cpu_init();  // a tree may be built from a static initializer, before libgcc's own call
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

// The leaf width to use: the one asked for, or the widest this CPU runs.
int leaf_width(int requested) {
    const std::vector<int> widths = kd_leaf_widths();
    if (requested == 0) return widths.back();
    if (std::find(widths.begin(), widths.end(), requested) == widths.end())
        throw Error("kd-tree leaves: width " + std::to_string(requested) + " is not one this CPU runs (" +
                    (requested == 8 ? "8 needs AVX2" : "the widths are 4 and 8") + ")");
    return requested;
}

class KdMeshAccelerator final : public TriangleAccelerator {
public:
    KdMeshAccelerator(KdStrategy strategy, const TriangleMesh& mesh, const BuildOptions& options,
                      const KdCostModel& cost)
        : m_name(kd_strategy_name(strategy)),
          m_tree(build(strategy, mesh, options, cost)),
          m_packets(options.triangle_test, leaf_width(options.leaf_width)) {
        lay_out_leaves(mesh, options.threads);
        m_tree.stats.bytes = static_cast<std::int64_t>(m_tree.nodes.size() * sizeof(KdNode) + m_packets.bytes());
        m_tree.stats.leaf_width = m_packets.width();
        m_root_leaf = !m_tree.nodes.empty() && !m_tree.bounds.is_empty() && m_tree.nodes[0].is_leaf() &&
                      m_tree.nodes[0].primitive_count() != 0;
    }

    std::string_view name() const override { return m_name; }

    bool intersect(const Ray& ray, MeshHit& hit) const override { return trace<false>(ray, hit); }

    bool occluded(const Ray& ray) const override {
        MeshHit ignored;
        return trace<true>(ray, ignored);
    }

    void intersect_packet(std::span<const Ray> rays, std::span<MeshHit> hits) const override {
        trace_packets<false>(rays, hits.data(), nullptr);
    }

    void occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const override {
        trace_packets<true>(rays, nullptr, blocked.data());
    }

    AccelStats stats() const override { return m_tree.stats; }

private:
    // Packets as wide as the leaves: 8 lanes where the CPU runs AVX2 leaves, the walk compiled for AVX2
    // with them; 4 lanes in the baseline instruction set otherwise.
    template <bool AnyHit>
    void trace_packets(std::span<const Ray> rays, MeshHit* hits, std::uint8_t* blocked) const {
        accel::dispatch_triangle_test(m_packets.test(), [&]<TriangleTest Test>() {
#if RTLAB_KD_HAVE_AVX2_LEAVES
            if (m_packets.width() == 8) {
                for (std::size_t i = 0; i < rays.size(); i += 8)
                    kd::trace_packet_avx2<Test, AnyHit>(m_tree, m_packets,
                                                        rays.subspan(i, std::min<std::size_t>(8, rays.size() - i)),
                                                        hits ? hits + i : nullptr, blocked ? blocked + i : nullptr);
                return;
            }
#endif
            for (std::size_t i = 0; i < rays.size(); i += 4)
                kd::trace_packet<Test, AnyHit, 4, 4>(m_tree, m_packets,
                                                     rays.subspan(i, std::min<std::size_t>(4, rays.size() - i)),
                                                     hits ? hits + i : nullptr, blocked ? blocked + i : nullptr);
        });
    }

    template <bool AnyHit>
    bool trace(const Ray& ray, MeshHit& hit) const {
        return accel::dispatch_triangle_test(m_packets.test(), [&]<TriangleTest Test>() {
            const kd::PacketRay<Test> r(ray);
            if (!r.valid()) return false;
            // test_leaf(leaf, closest, found): the leaf test of kd_traverse, writing its hit to found.
            const auto run = [&](auto test_leaf) {
                if (m_root_leaf) return trace_root_leaf(ray, hit, test_leaf);
                return kd_traverse<AnyHit>(
                    m_tree, ray, [&](const KdNode& leaf, float& closest) { return test_leaf(leaf, closest, hit); });
            };
#if RTLAB_KD_HAVE_AVX2_LEAVES
            // Packets of 8: the walk stays in the baseline instruction set (it gains nothing from AVX2) and
            // calls the AVX2 leaf test, about once per ray.
            if (m_packets.width() == 8) {
                return run([&](const KdNode& leaf, float& closest, MeshHit& found) {
                    return kd::test_packets_avx2<Test, AnyHit>(m_packets, r, leaf.primitive_offset(),
                                                               leaf.primitive_count(), closest, found);
                });
            }
#endif
            return run([&](const KdNode& leaf, float& closest, MeshHit& found) {
                return kd::test_packets<Test, AnyHit, 4>(m_packets, r, leaf.primitive_offset(), leaf.primitive_count(),
                                                         closest, found);
            });
        });
    }

    // trace() of a tree that is one leaf (a few triangles: the Cornell box's walls and light in a scene's flat tree):
    // its root box clip and its leaf test, with no walk set up. The clip stays: it can reject a ray lying in or along
    // the triangles' planes that the leaf test would take, and the packet walk clips too. Every ray of the path tracer
    // meets that tree twice: cornell_box_bunny render 29.1 M -> 27.9 M Ir (callgrind). The clip comes after the
    // test, as it only decides whether a hit counts: most shadow rays inside the box find none there and skip it
    // (27.73 M -> 27.52 M Ir).
    template <class LeafTest>
    bool trace_root_leaf(const Ray& ray, MeshHit& hit, LeafTest& test_leaf) const {
        float closest = ray.tmax;
        MeshHit found;
        if (!test_leaf(m_tree.nodes[0], closest, found)) return false;
        // An origin strictly inside the box with tmin <= 0 < tmax passes the clip whatever the direction (every
        // near-plane distance is <= 0, every far one >= 0, neither NaN), so the rays that bounce inside a room skip
        // it (27.52 M -> 27.24 M Ir).
        const AABB& box = m_tree.bounds;
        const Point3& o = ray.origin;
        const bool inside = ray.tmin <= 0.0f && ray.tmax > 0.0f && box.lo.x < o.x && o.x < box.hi.x && box.lo.y < o.y &&
                            o.y < box.hi.y && box.lo.z < o.z && o.z < box.hi.z;
        float t0, t1;
        if (!inside && !BoxRay(ray).clip(box, ray.tmax, t0, t1)) return false;
        hit = found;
        return true;
    }

    static KdTreeData build(KdStrategy strategy, const TriangleMesh& mesh, const BuildOptions& options,
                            const KdCostModel& cost) {
        KdBuildInput input;
        input.bounds.resize(mesh.triangle_count());
        accel::run_on_threads(options.threads, [&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.triangle_count(), 4096),
                              [&](const tbb::blocked_range<std::size_t>& r) {
                                  for (std::size_t i = r.begin(); i != r.end(); ++i)
                                      input.bounds[i] = mesh.is_degenerate(i) ? AABB{} : mesh.triangle_bounds(i);
                              });
        });
        input.clip = [&mesh](std::uint32_t i, const AABB& box) {
            return accel::clip_triangle(mesh.corner(i, 0), mesh.corner(i, 1), mesh.corner(i, 2), box);
        };
        return build_kd_tree(input, strategy, cost, options.threads);
    }

    // Copies each leaf's triangles into consecutive packets (one cache-line run per leaf for incoherent
    // rays) and renumbers the leaf to (packet count, first packet). The statistics keep triangle counts.
    // The leaves' first packets are counted first, in tree order, so that the packets are allocated once
    // and the leaves filled in parallel.
    void lay_out_leaves(const TriangleMesh& mesh, int threads) {
        std::vector<std::uint32_t> leaves, firsts;
        std::size_t packets = 0;
        for (std::uint32_t n = 0; n < m_tree.nodes.size(); ++n) {
            const KdNode& node = m_tree.nodes[n];
            if (!node.is_leaf() || node.primitive_count() == 0) continue;
            leaves.push_back(n);
            firsts.push_back(static_cast<std::uint32_t>(packets));
            packets += m_packets.packets_for(node.primitive_count());
        }
        m_packets.allocate(packets);
        const auto width = static_cast<std::size_t>(m_packets.width());
        accel::run_on_threads(threads, [&] {
            tbb::parallel_for(
                tbb::blocked_range<std::size_t>(0, leaves.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
                    // A range's leaves share these lists (two allocations per leaf before: 12,000 on the bunny).
                    std::vector<Placed> placed;
                    std::vector<std::uint32_t> triangles;
                    for (std::size_t k = r.begin(); k != r.end(); ++k) {
                        KdNode& node = m_tree.nodes[leaves[k]];
                        const std::uint32_t count = node.primitive_count();
                        const std::uint32_t one = node.primitive_offset();
                        const std::span<const std::uint32_t> listed =
                            count == 1 ? std::span<const std::uint32_t>(&one, 1)
                                       : std::span<const std::uint32_t>(
                                             m_tree.primitive_indices.data() + node.primitive_offset(), count);
                        grouped_compactly(mesh, listed, width, placed, triangles);
                        m_packets.fill_leaf(mesh, triangles, firsts[k]);
                        node = KdNode::leaf(m_packets.packets_for(count), firsts[k]);
                    }
                });
        });
        std::vector<std::uint32_t>().swap(m_tree.primitive_indices);
    }

    // A leaf's triangles ordered so that each run of `width` (one packet) lies close together: the widest spread of
    // centroids halved at a multiple of width, and each half in turn, so that a packet's box (the packet walk's
    // cull) is small.
    struct Placed {
        Point3 centroid;
        std::uint32_t triangle;
    };
    // Into `triangles`, with `placed` as the working list (both replaced).
    static void grouped_compactly(const TriangleMesh& mesh, std::span<const std::uint32_t> listed, std::size_t width,
                                  std::vector<Placed>& placed, std::vector<std::uint32_t>& triangles) {
        placed.resize(listed.size());
        for (std::size_t j = 0; j < listed.size(); ++j) {
            const std::uint32_t i = listed[j];
            placed[j] = {(mesh.corner(i, 0) + mesh.corner(i, 1) + mesh.corner(i, 2)) / 3.0f, i};
        }
        group(placed, width);
        triangles.resize(listed.size());
        for (std::size_t j = 0; j < placed.size(); ++j) triangles[j] = placed[j].triangle;
    }
    static void group(std::span<Placed> placed, std::size_t width) {
        if (placed.size() <= width) return;
        AABB spread;
        for (const Placed& p : placed) spread.expand(p.centroid);
        const Vec3 extent = spread.hi - spread.lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const std::size_t packets = (placed.size() + width - 1) / width;
        const std::size_t middle = (packets + 1) / 2 * width;
        std::nth_element(placed.begin(), placed.begin() + static_cast<std::ptrdiff_t>(middle), placed.end(),
                         [axis](const Placed& a, const Placed& b) {
                             const float ca = a.centroid[axis], cb = b.centroid[axis];
                             return ca < cb || (ca == cb && a.triangle < b.triangle);
                         });
        group(placed.first(middle), width);
        group(placed.subspan(middle), width);
    }

    std::string m_name;
    KdTreeData m_tree;
    kd::TrianglePackets m_packets;
    bool m_root_leaf = false;  // the root is a leaf with triangles (the tree's only node but for node 1's padding)
};

}  // namespace

std::vector<int> kd_leaf_widths() {
    if (cpu_has_avx2()) return {4, 8};
    return {4};
}

std::vector<std::string> kd_tree_methods() {
    std::vector<std::string> methods;
    for (KdStrategy s : kKdStrategies) methods.emplace_back(kd_strategy_name(s));
    return methods;
}

std::unique_ptr<TriangleAccelerator> make_kd_tree(std::string_view method, const TriangleMesh& mesh,
                                                  const BuildOptions& options) {
    return make_kd_tree(method, mesh, options, kd_mesh_cost_model());
}

std::unique_ptr<TriangleAccelerator> make_kd_tree(std::string_view method, const TriangleMesh& mesh,
                                                  const BuildOptions& options, const KdCostModel& cost) {
    return std::make_unique<KdMeshAccelerator>(parse_kd_strategy(method), mesh, options, cost);
}

}  // namespace rtlab
