#pragma once
// The kd-tree walk for a packet of up to W rays whose directions share one octant (camera rays of a pixel
// tile, shadow rays towards one point). Each lane keeps the interval, margins and early-outs of its own
// single walk (kd_traverse.hpp), computed by the same operations on the same floats, so every ray is
// tested against exactly the leaves its single walk tests, in the same order, with the same closest hit so
// far: its answer is the single walk's, bit for bit, ties between triangles at equal t included. What the
// lanes share is the node: one load, one plane distance for all lanes in SIMD, one decision where to go.
//
// Why the order is the same: within one octant the near child of a node is the same for every lane, and
// the packet goes depth first, near child first, as each single walk does. A lane takes part in a subtree
// only where its single walk enters it; in between it waits, its state untouched. Its single walk's stack
// is the packet's stack restricted to the entries that hold the lane, except for the entries where the lane
// skipped the near child: its single walk goes to the far child at once, without the pop() test, so the
// entry marks the lane `direct` and pop() lets it through unchecked.
#include <rtlab/accel/kd_node.hpp>
#include <rtlab/accel/kd_traverse.hpp>
#include <rtlab/core/box_ray.hpp>

#include "kd_packets.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

namespace rtlab::kd {

/// What kd_traverse and kd_walk compute for one ray before the first node, with the same operations.
struct WalkStart {
    float origin[3], inv[3];
    float tmin, tmax;  ///< the root interval, tmax already widened by overlap
    float overlap;     ///< two of the ray's absolute margins
    float end_slack;   ///< +inf for a ray with a zero direction component
    unsigned octant;   ///< sign bits of the direction
    /// False when the single walk answers a miss before its first node.
    bool start(const KdTreeData& tree, const Ray& ray) {
        if (tree.nodes.empty() || tree.bounds.is_empty() || !is_finite(ray.origin) || !is_finite(ray.direction))
            return false;
        const BoxRay box_ray(ray);
        if (!box_ray.clip(tree.bounds, ray.tmax, tmin, tmax)) return false;
        octant = static_cast<unsigned>(box_ray.negative[0] | box_ray.negative[1] << 1 | box_ray.negative[2] << 2);
        overlap = 2.0f * kKdIntervalMargin * std::max(std::abs(tmin), std::abs(tmax));
        tmax += overlap;
        for (int a = 0; a < 3; ++a) {
            origin[a] = box_ray.origin[a];
            inv[a] = box_ray.inv[a];
        }
        end_slack =
            std::isinf(box_ray.inv[0]) | std::isinf(box_ray.inv[1]) | std::isinf(box_ray.inv[2]) ? kInfinity : overlap;
        return true;
    }
};

/// One packet's walk: lanes `alive` of `starts` (one octant), leaves tested per lane by test_packets of
/// width LeafW. Closest-hit: hits[lane] and the lane's bit in the result on a hit; any-hit: the bit alone.
template <TriangleTest Test, bool AnyHit, int W, int LeafW>
class PacketWalk {
public:
    using F = typename Lanes<W>::F;
    using I = typename Lanes<W>::I;

    [[gnu::always_inline]] static int run(const KdTreeData& tree, const TrianglePackets& packets,
                                          const std::optional<PacketRay<Test>>* rays, const Ray* const* source,
                                          const WalkStart* starts, int alive, unsigned octant, MeshHit* hits) {
        PacketWalk walk;
        for (int lane = 0; lane < W; ++lane) {
            const bool on = (alive >> lane) & 1;
            const WalkStart& s = starts[lane];
            for (int a = 0; a < 3; ++a) {
                walk.m_origin[a][lane] = on ? s.origin[a] : 0.0f;
                walk.m_inv[a][lane] = on ? s.inv[a] : 0.0f;
            }
            walk.m_tmin[lane] = on ? s.tmin : 0.0f;
            walk.m_tmax[lane] = on ? s.tmax : 0.0f;
            walk.m_overlap[lane] = on ? s.overlap : 0.0f;
            walk.m_end_slack[lane] = on ? s.end_slack : 0.0f;
            walk.m_closest[lane] = on ? source[lane]->tmax : 0.0f;
            walk.m_closest_reach[lane] = walk.m_closest[lane] + walk.m_overlap[lane];
            walk.m_closest_end[lane] = walk.m_closest_reach[lane] + walk.m_end_slack[lane];
        }
        walk.m_alive = alive;
        return walk.walk(tree, packets, rays, octant, hits);
    }

private:
    struct Entry {
        F tmin, tmax;
        std::uint32_t node;
        int lanes;   // the lanes that visit the node
        int direct;  // those of them whose single walk goes there without a stack entry
    };

    [[gnu::always_inline]] int walk(const KdTreeData& tree, const TrianglePackets& packets,
                                    const std::optional<PacketRay<Test>>* rays, unsigned octant, MeshHit* hits) {
        const KdNode* nodes = tree.nodes.data();
        Entry stack[64];  // deeper than any tree the builders make (their depth cap is 60)
        Entry* top = stack;
        std::uint32_t index = 0;
        int active = m_alive, result = 0;
        F tmin = m_tmin, tmax = m_tmax;
        for (;;) {
            const KdNode node = nodes[index];
            if (!node.is_leaf()) {
                // The single walk's step, lane by lane (see kd_walk): the same plane distance, the same
                // comparisons (NaN failing every one), the same ends of the children's intervals.
                const auto axis = static_cast<std::uint32_t>(node.axis());
                const std::uint32_t empty = node.empty_children();
                const std::uint32_t side = (octant >> axis) & 1u;
                const F t_plane = (splat<W>(node.split()) - m_origin[axis]) * m_inv[axis];
                const F t_near_end = t_plane + m_overlap;
                const std::uint32_t near = node.children() | side;
                const int want_near = (empty & (1u << side)) != 0 ? 0 : active & ~lane_bits(t_near_end < tmin);
                const int want_far = (empty & (2u >> side)) != 0 ? 0 : active & ~lane_bits(t_plane > tmax);
                if (want_near != 0) {
                    if (want_far != 0) {
                        *top = Entry{t_plane > tmin ? t_plane : tmin, tmax, near ^ 1u, want_far, want_far & ~want_near};
                        ++top;
                    }
                    tmax = t_near_end < tmax ? t_near_end : tmax;
                    active = want_near;
                    index = near;
                    continue;
                }
                if (want_far != 0) {
                    tmin = t_plane > tmin ? t_plane : tmin;
                    active = want_far;
                    index = near ^ 1u;
                    continue;
                }
            } else if (node.primitive_count() != 0) {
                for (int lanes = active; lanes != 0; lanes &= lanes - 1) {
                    const int lane = __builtin_ctz(static_cast<unsigned>(lanes));
                    float& closest = m_closest[lane];
                    if (!test_packets<Test, AnyHit, LeafW>(packets, *rays[lane], node.primitive_offset(),
                                                           node.primitive_count(), closest, hits[lane]))
                        continue;
                    result |= 1 << lane;
                    if constexpr (AnyHit) {
                        m_alive &= ~(1 << lane);
                    } else {
                        m_closest_reach[lane] = closest + m_overlap[lane];
                        m_closest_end[lane] = m_closest_reach[lane] + m_end_slack[lane];
                    }
                }
                if (AnyHit && m_alive == 0) break;
            }
            // pop(): the next stacked node with a lane still to visit it. Closest-hit: a lane whose single
            // walk would pop the entry skips it when it begins past closest_reach and ends its walk when it
            // begins past closest_end, as the single walk does.
            bool popped = false;
            while (top != stack) {
                --top;
                int lanes = top->lanes & m_alive;
                if constexpr (!AnyHit) {
                    const int checked = lanes & ~top->direct;
                    if (checked != 0) {
                        const int past = checked & lane_bits(m_closest_reach < top->tmin);
                        if (past != 0) {
                            m_alive &= ~(past & lane_bits(m_closest_end < top->tmin));
                            lanes &= ~past;
                        }
                    }
                }
                if (lanes == 0) continue;
                active = lanes;
                index = top->node;
                tmin = top->tmin;
                tmax = top->tmax;
                popped = true;
                break;
            }
            if (!popped) break;
        }
        return result;
    }

    F m_origin[3], m_inv[3];
    F m_tmin, m_tmax, m_overlap, m_end_slack;
    F m_closest_reach, m_closest_end;
    float m_closest[W];
    int m_alive = 0;
};

/// Traces up to W rays (rays.size() <= W) as packets, one per octant among them; hits or blocked get each
/// ray's answer (hits for closest-hit, blocked for any-hit).
template <TriangleTest Test, bool AnyHit, int W, int LeafW>
[[gnu::always_inline]] inline void trace_packet(const KdTreeData& tree, const TrianglePackets& packets,
                                                std::span<const Ray> rays, MeshHit* hits, std::uint8_t* blocked) {
    std::optional<PacketRay<Test>> packet_rays[W];
    const Ray* source[W];
    WalkStart starts[W];
    MeshHit lane_hits[W];
    int pending = 0;
    const int n = static_cast<int>(rays.size());
    for (int lane = 0; lane < n; ++lane) {
        source[lane] = &rays[static_cast<std::size_t>(lane)];
        packet_rays[lane].emplace(*source[lane]);
        // A ray the single trace answers as a miss before the walk (an invalid leaf ray, a ray missing the
        // root box) is left out.
        if (packet_rays[lane]->valid() && starts[lane].start(tree, *source[lane])) pending |= 1 << lane;
    }
    int result = 0;
    while (pending != 0) {
        const unsigned octant = starts[__builtin_ctz(static_cast<unsigned>(pending))].octant;
        int lanes = 0;
        for (int rest = pending; rest != 0; rest &= rest - 1) {
            const int lane = __builtin_ctz(static_cast<unsigned>(rest));
            if (starts[lane].octant == octant) lanes |= 1 << lane;
        }
        pending &= ~lanes;
        result |= PacketWalk<Test, AnyHit, W, LeafW>::run(tree, packets, packet_rays, source, starts, lanes, octant,
                                                          lane_hits);
    }
    for (int lane = 0; lane < n; ++lane) {
        const bool hit = (result >> lane) & 1;
        if constexpr (AnyHit)
            blocked[lane] = hit ? 1 : 0;
        else
            hits[lane] = hit ? lane_hits[lane] : MeshHit{};
    }
}

#if RTLAB_KD_HAVE_AVX2_LEAVES
/// Packets of 8 with AVX2 (only on CPUs that have it): the walk and its leaf tests compiled for AVX2, as
/// test_packets_avx2 (no FMA, so every lane rounds as the single walk and the scalar tests do).
template <TriangleTest Test, bool AnyHit>
[[gnu::target("avx2"), gnu::noinline]] void trace_packet_avx2(const KdTreeData& tree, const TrianglePackets& packets,
                                                              std::span<const Ray> rays, MeshHit* hits,
                                                              std::uint8_t* blocked) {
    trace_packet<Test, AnyHit, 8, 8>(tree, packets, rays, hits, blocked);
}
#endif

}  // namespace rtlab::kd
