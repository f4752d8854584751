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
#include <new>
#include <span>
#include <type_traits>

namespace rtlab::kd {

/// Storage for a T constructed later (or never): an array of them costs no initialisation.
template <class T>
union Deferred {
    static_assert(std::is_trivially_destructible_v<T>);
    Deferred() {}
    T value;
};

/// lane_bits for the walk: 8 lanes in one vmovmskps rather than two halves (the generic lane_bits cannot
/// use an AVX intrinsic: it would not inline into these target-independent templates; inline assembly does,
/// and the walk of 8 lanes runs only inside trace_packet_avx2). 2.4% fewer instructions in the packet walks
/// (bunny, callgrind).
template <int W>
[[gnu::always_inline]] inline int walk_lane_bits(const typename Lanes<W>::I& mask) {
#if RTLAB_KD_HAVE_AVX2_LEAVES
    if constexpr (W == 8) {
        int bits;
        asm("vmovmskps %1, %0" : "=r"(bits) : "x"(mask));
        return bits;
    }
#endif
    return lane_bits(mask);
}

/// BoxRay::enlarge on every lane (a function, not a lambda: a lambda would not take the AVX2 target of
/// the walk that calls it when it is not inlined).
template <int W>
[[gnu::always_inline]] inline typename Lanes<W>::F enlarge_lanes(const typename Lanes<W>::F& t) {
    constexpr float kTwoGamma3 = 2.0f * gamma_bound(3);
    return t * (t > splat<W>(0.0f) ? splat<W>(1.0f + kTwoGamma3) : splat<W>(1.0f - kTwoGamma3));
}

/// One packet's walk over the lanes `alive` (one octant); a leaf's packets of LeafW triangles tested one after
/// another by the lanes that may reach each (test_one_packet). Closest-hit: hits[lane] and the lane's bit in the result
/// on a hit; any-hit: the bit alone.
template <TriangleTest Test, bool AnyHit, int W, int LeafW>
class PacketWalk {
public:
    using F = typename Lanes<W>::F;
    using I = typename Lanes<W>::I;

    /// Each lane's origin, inverse direction, root interval [tmin, tmax] (tmax widened by overlap), overlap,
    /// end slack, ray.tmin and ray.tmax, as kd_traverse and kd_walk compute them.
    struct Start {
        F origin[3], inv[3];
        F tmin, tmax, overlap, end_slack, ray_tmin, ray_tmax;
    };

    [[gnu::always_inline]] static int run(const KdTreeData& tree, const TrianglePackets& packets,
                                          const Deferred<PacketRay<Test>>* rays, const Start& start, int alive,
                                          unsigned octant, MeshHit* hits) {
        PacketWalk walk(start, alive);
        // One walk per octant, as kd_traverse: the near side of each axis a constant, and branches of its
        // own for the predictor (bunny and dragon, 1 thread, same-run ratios to rtcIntersect8 over two runs
        // each: shadow rays 0.47-0.84 -> 0.66-0.89 any-hit, primary any-hit 0.75-1.07 -> 0.82-1.30).
        return detail::with_octant(
            octant, [&]<unsigned Octant>() __attribute__((always_inline)) {
                return walk.template walk<Octant>(tree, packets, rays, hits);
            });
    }

private:
    struct Entry {
        F tmin, tmax;
        std::uint32_t node;
        int lanes;   // the lanes that visit the node
        int direct;  // those of them whose single walk goes there without a stack entry
    };

    [[gnu::always_inline]] PacketWalk(const Start& s, int alive)
        : m_origin{s.origin[0], s.origin[1], s.origin[2]},
          m_inv{s.inv[0], s.inv[1], s.inv[2]},
          m_tmin(s.tmin),
          m_tmax(s.tmax),
          m_overlap(s.overlap),
          m_end_slack(s.end_slack),
          m_cull_from(s.ray_tmin - s.overlap),
          m_closest_reach(s.ray_tmax + s.overlap),
          m_closest_end(m_closest_reach + s.end_slack),
          m_alive(alive) {
        for (int lane = 0; lane < W; ++lane) m_closest[lane] = s.ray_tmax[lane];
    }

    template <unsigned Octant>
    [[gnu::always_inline]] int walk(const KdTreeData& tree, const TrianglePackets& packets,
                                    const Deferred<PacketRay<Test>>* rays, MeshHit* hits) {
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
                const std::uint32_t side = (Octant >> axis) & 1u;
                const F t_plane = (splat<W>(node.split()) - m_origin[axis]) * m_inv[axis];
                const F t_near_end = t_plane + m_overlap;
                const std::uint32_t near = node.children() | side;
                const int want_near = (empty & (1u << side)) != 0 ? 0 : active & ~walk_lane_bits<W>(t_near_end < tmin);
                const int want_far = (empty & (2u >> side)) != 0 ? 0 : active & ~walk_lane_bits<W>(t_plane > tmax);
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
                // The leaf's lines asked for once, not once per ray.
                const std::uint32_t first = node.primitive_offset(), end = first + node.primitive_count();
                prefetch_packets(packets, first, node.primitive_count());
                // Packet after packet, each tested by the lanes whose segment may reach its box: a lane meets the
                // leaf's packets in the order its single walk's leaf test meets them, with the same closest hit
                // before each, and skips only packets it cannot hit. Only with the watertight test, whose hits
                // lie in their triangles: Moller-Trumbore and the plane test take some rays grazing a face that
                // pass outside its box (tests/accel/packet_test.cpp, the cube lattice: 2-72 rays of 3,938).
                int lanes = active, found = 0;
                for (std::uint32_t k = first; k < end && lanes != 0; ++k) {
                    int reach = lanes;
                    if constexpr (Test == TriangleTest::watertight) reach &= reaches_box<Octant>(packets.bounds(k));
                    for (; reach != 0; reach &= reach - 1) {
                        const int lane = __builtin_ctz(static_cast<unsigned>(reach));
                        if (!test_one_packet<Test, AnyHit, LeafW>(packets, rays[lane].value, k, m_closest[lane],
                                                                  hits[lane]))
                            continue;
                        found |= 1 << lane;
                        if constexpr (AnyHit) lanes &= ~(1 << lane);
                    }
                }
                result |= found;
                if constexpr (AnyHit) {
                    m_alive &= ~found;
                    if (m_alive == 0) break;
                } else {
                    for (int hit = found; hit != 0; hit &= hit - 1) {
                        const int lane = __builtin_ctz(static_cast<unsigned>(hit));
                        m_closest_reach[lane] = m_closest[lane] + m_overlap[lane];
                        m_closest_end[lane] = m_closest_reach[lane] + m_end_slack[lane];
                    }
                }
            }
            // pop(): the next stacked node with a lane still to visit it. Closest-hit: a lane whose single
            // walk would pop the entry skips it when it begins past closest_reach and ends its walk when it
            // begins past closest_end, as the single walk does.
            bool popped = false;
            while (top != stack && m_alive != 0) {
                --top;
                int lanes = top->lanes & m_alive;
                if constexpr (!AnyHit) {
                    const int checked = lanes & ~top->direct;
                    if (checked != 0) {
                        const int past = checked & walk_lane_bits<W>(m_closest_reach < top->tmin);
                        if (past != 0) {
                            m_alive &= ~(past & walk_lane_bits<W>(m_closest_end < top->tmin));
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

    // The lanes whose segment (ray tmin, closest hit) may meet the box (lo xyz, hi xyz) of a packet of triangles:
    // a slab test over the segment widened by the lane's overlap at both ends, far plane distances enlarged as
    // BoxRay::clip enlarges them. A hit the leaf test accepts lies within the overlap of where the ray meets the
    // triangle, as kd_walk's early end assumes; a NaN plane distance (a ray in a slab's plane) bounds nothing.
    template <unsigned Octant>
    [[gnu::always_inline]] int reaches_box(const float* box) const {
        F t_enter = m_cull_from;
        F t_leave = load_lanes<W>(m_closest) + m_overlap;
        for (int a = 0; a < 3; ++a) {
            const bool negative = (Octant >> a) & 1u;
            const F near_t = (splat<W>(box[negative ? 3 + a : a]) - m_origin[a]) * m_inv[a];
            const F far_t = enlarge_lanes<W>((splat<W>(box[negative ? a : 3 + a]) - m_origin[a]) * m_inv[a]);
            t_enter = near_t > t_enter ? near_t : t_enter;
            t_leave = far_t < t_leave ? far_t : t_leave;
        }
        return ~walk_lane_bits<W>(t_enter > t_leave);
    }

    F m_origin[3], m_inv[3];
    F m_tmin, m_tmax, m_overlap, m_end_slack, m_cull_from;
    F m_closest_reach, m_closest_end;
    float m_closest[W];
    int m_alive = 0;
};

/// Traces up to W rays (rays.size() <= W) as packets, one per octant among them; hits or blocked get each
/// ray's answer (hits for closest-hit, blocked for any-hit).
template <TriangleTest Test, bool AnyHit, int W, int LeafW>
[[gnu::always_inline]] inline void trace_packet(const KdTreeData& tree, const TrianglePackets& packets,
                                                std::span<const Ray> rays, MeshHit* hits, std::uint8_t* blocked) {
    using Walk = PacketWalk<Test, AnyHit, W, LeafW>;
    using F = typename Lanes<W>::F;
    using I = typename Lanes<W>::I;
    const int n = static_cast<int>(rays.size());
    // What kd_traverse, BoxRay and kd_walk compute for each ray before the first node, on all lanes at
    // once: the same operations on the same floats. Lanes past n hold a ray that the clip keeps out.
    typename Walk::Start s;
    F d[3];
    for (int lane = 0; lane < n; ++lane) {
        const Ray& r = rays[static_cast<std::size_t>(lane)];
        for (int a = 0; a < 3; ++a) {
            s.origin[a][lane] = r.origin[a];
            d[a][lane] = r.direction[a];
        }
        s.ray_tmin[lane] = r.tmin;
        s.ray_tmax[lane] = r.tmax;
    }
    for (int lane = n; lane < W; ++lane) {
        for (int a = 0; a < 3; ++a) {
            s.origin[a][lane] = 0.0f;
            d[a][lane] = 1.0f;
        }
        s.ray_tmin[lane] = 1.0f;
        s.ray_tmax[lane] = 0.0f;
    }
    const F inf = splat<W>(kInfinity);
    const I finite = (abs_lanes<W>(s.origin[0]) < inf) & (abs_lanes<W>(s.origin[1]) < inf) &
                     (abs_lanes<W>(s.origin[2]) < inf) & (abs_lanes<W>(d[0]) < inf) & (abs_lanes<W>(d[1]) < inf) &
                     (abs_lanes<W>(d[2]) < inf);
    int valid = walk_lane_bits<W>(finite) & ((1 << n) - 1);
    if (tree.nodes.empty() || tree.bounds.is_empty()) valid = 0;
    // BoxRay::clip against the root box.
    F t0 = s.ray_tmin, t1 = enlarge_lanes<W>(s.ray_tmax);
    unsigned octant_bits[3];
    for (int a = 0; a < 3; ++a) {
        s.inv[a] = splat<W>(1.0f) / d[a];
        const I negative = reinterpret_cast<I>(s.inv[a]) < 0;  // the sign bit, -0 and -inf included
        octant_bits[a] = static_cast<unsigned>(walk_lane_bits<W>(negative));
        const F lo = splat<W>(tree.bounds.lo[a]), hi = splat<W>(tree.bounds.hi[a]);
        const F near_plane = negative ? hi : lo, far_plane = negative ? lo : hi;
        const F near_t = (near_plane - s.origin[a]) * s.inv[a];
        const F far_t = enlarge_lanes<W>((far_plane - s.origin[a]) * s.inv[a]);
        t0 = near_t > t0 ? near_t : t0;
        t1 = far_t < t1 ? far_t : t1;
    }
    valid &= walk_lane_bits<W>(t0 <= t1);
    // The leaf tests' per-ray constants, only for rays that reach the root box (most camera rays of a view
    // with the mesh in the middle do not: 10% fewer instructions in the packet walks of rtlab-accel --packets,
    // bunny, callgrind); a ray the single trace answers as a miss for its leaf test (an
    // invalid PacketRay: one with a zero direction, its origin and direction being finite here) is left out, as it
    // is there before the walk. The lanes' checks side by side rather than each PacketRay's own: 3.5% fewer
    // instructions in the closest-hit packet walk (bunny --packets, callgrind).
    if constexpr (Test == TriangleTest::watertight) {
        const F zero{};
        valid &= walk_lane_bits<W>((d[0] != zero) | (d[1] != zero) | (d[2] != zero));
    }
    Deferred<PacketRay<Test>> packet_rays[W];
    for (int rest = valid; rest != 0; rest &= rest - 1) {
        const int lane = __builtin_ctz(static_cast<unsigned>(rest));
        new (&packet_rays[lane].value) PacketRay<Test>(rays[static_cast<std::size_t>(lane)], true);
    }
    // kd_walk's margins: overlap from max(|tmin|, |tmax|) as std::max takes it, end_slack +inf for a zero
    // direction component.
    const F a0 = abs_lanes<W>(t0), a1 = abs_lanes<W>(t1);
    s.overlap = splat<W>(2.0f * kKdIntervalMargin) * (a0 < a1 ? a1 : a0);
    s.tmin = t0;
    s.tmax = t1 + s.overlap;
    const I zero_component =
        (abs_lanes<W>(s.inv[0]) == inf) | (abs_lanes<W>(s.inv[1]) == inf) | (abs_lanes<W>(s.inv[2]) == inf);
    s.end_slack = zero_component ? inf : s.overlap;

    MeshHit lane_hits[W];
    int result = 0;
    for (int pending = valid; pending != 0;) {
        const int first = __builtin_ctz(static_cast<unsigned>(pending));
        const unsigned octant = ((octant_bits[0] >> first) & 1u) | ((octant_bits[1] >> first) & 1u) << 1 |
                                ((octant_bits[2] >> first) & 1u) << 2;
        // The pending lanes whose sign bits are the first one's.
        int lanes = pending;
        for (int a = 0; a < 3; ++a) lanes &= static_cast<int>((octant >> a) & 1u ? octant_bits[a] : ~octant_bits[a]);
        pending &= ~lanes;
        result |= Walk::run(tree, packets, packet_rays, s, lanes, octant, lane_hits);
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
