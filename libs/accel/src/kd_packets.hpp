#pragma once
// A kd-tree's leaves laid out for one triangle test: each leaf's triangles in packets of W (4 or 8), one
// structure-of-arrays block per packet, tested W at a time. The arithmetic of every lane is the scalar
// test's own, operation for operation (no fused multiply-add: neither the baseline x86-64 target nor the
// AVX2 target below has it), so a packet answers exactly as the scalar tests of triangle_intersect.hpp do --
// the watertight test's double-precision fallback included, which runs for the rare lane whose edge
// function rounds to zero. Packets of 4 use the baseline instruction set and are inlined into the walk;
// packets of 8 are compiled for AVX2 in a function of their own, called once per leaf, and chosen at run
// time on CPUs that have it (see kd_mesh.cpp).
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <vector>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define RTLAB_KD_HAVE_AVX2_LEAVES 1
#endif

namespace rtlab::kd {

/// W lanes of floats or 32-bit integers (GCC's vector extension), one triangle per lane.
template <int W>
struct Lanes {
    // typedef, not using: GCC drops the attribute from a dependent alias declaration.
    typedef float F __attribute__((vector_size(4 * W)));
    typedef std::int32_t I __attribute__((vector_size(4 * W)));
};

/// x in every lane: one broadcast. The sum with the zero vector this was kept an addition a splat (GCC must: x + 0
/// is +0 for x = -0), 7% of the closest-hit packet walk's instructions (bunny --packets, callgrind); a list
/// initializer, a difference with zero or a shuffle of lane 0 became inserts or blends. Eight lanes run only in the
/// AVX2 walks and leaf tests, where inline assembly inlines and an AVX intrinsic would not (see walk_lane_bits).
template <int W>
[[gnu::always_inline]] inline typename Lanes<W>::F splat(float x) {
#if RTLAB_KD_HAVE_AVX2_LEAVES
    if constexpr (W == 8) {
        typename Lanes<W>::F v;
        asm("vbroadcastss %1, %0" : "=x"(v) : "xm"(x));
        return v;
    }
#endif
#if defined(__SSE__)
    if constexpr (W == 4) return reinterpret_cast<typename Lanes<W>::F>(_mm_set1_ps(x));
#endif
    return typename Lanes<W>::F{} + x;
}
template <int W>
[[gnu::always_inline]] inline typename Lanes<W>::F abs_lanes(const typename Lanes<W>::F& x) {
    using I = typename Lanes<W>::I;
    return reinterpret_cast<typename Lanes<W>::F>(reinterpret_cast<I>(x) & 0x7FFFFFFF);
}

template <int W>
[[gnu::always_inline]] inline typename Lanes<W>::F load_lanes(const float* p) {
    typename Lanes<W>::F x;
    std::memcpy(&x, p, sizeof(x));
    return x;
}

/// Bit i set when lane i of the mask is true (all bits of the lane set).
[[gnu::always_inline]] inline int lane_bits(const Lanes<4>::I& mask) {
#if defined(__SSE__)
    return _mm_movemask_ps(reinterpret_cast<__m128>(mask));
#else
    return (mask[0] ? 1 : 0) | (mask[1] ? 2 : 0) | (mask[2] ? 4 : 0) | (mask[3] ? 8 : 0);
#endif
}
/// Eight lanes as two halves of four: no AVX intrinsic here, so that the packet test stays one generic
/// template (an AVX2 intrinsic cannot be inlined into it); inside the AVX2 function this compiles to two
/// vmovmskps and a lane permute.
[[gnu::always_inline]] inline int lane_bits(const Lanes<8>::I& mask) {
    const Lanes<4>::I low = __builtin_shufflevector(mask, mask, 0, 1, 2, 3);
    const Lanes<4>::I high = __builtin_shufflevector(mask, mask, 4, 5, 6, 7);
    return lane_bits(low) | lane_bits(high) << 4;
}

/// Rows of W 32-bit lanes in one packet: corners for watertight, p0 and both edges for Moller-Trumbore,
/// the plane data (its two axis numbers stored as floats) for the plane test; then the mesh's triangle
/// indices, in the cache line that the last data row has already brought in.
constexpr int packet_rows(TriangleTest test) { return test == TriangleTest::plane ? 14 : 10; }

/// \brief Packets of `width` triangles (4 or 8) for one triangle test. Packet k holds rows x width floats;
/// a leaf whose count is not a multiple of the width repeats its last triangle (a repeated triangle cannot
/// change a hit).
class TrianglePackets {
public:
    TrianglePackets() = default;
    TrianglePackets(TriangleTest test, int width) : m_test(test), m_rows(packet_rows(test)), m_width(width) {}

    TriangleTest test() const { return m_test; }
    int width() const { return m_width; }
    /// Packets holding `count` triangles.
    std::uint32_t packets_for(std::uint32_t count) const {
        return (count + static_cast<std::uint32_t>(m_width) - 1) / static_cast<std::uint32_t>(m_width);
    }
    /// Room for `packets` packets, to be filled by fill_leaf (sized once: growing packet by packet moved
    /// the whole array again and again).
    /// Left uninitialized: fill_leaf writes every float of every packet (each row of every lane, a short
    /// leaf's last lanes repeating its last triangle). Zeroed first, the bunny's 5 MB cost a serial pass
    /// before the parallel fill, and the fresh pages' faults fell in it: a quarter of the page faults of
    /// a bunny build (perf, page-faults event).
    void allocate(std::size_t packets) {
        m_data.allocate(packets * packet_floats());
        m_bounds.allocate(packets * 6);
    }
    /// Writes a leaf's triangles (mesh indices) into packets_for(size) packets from packet `first`. Leaves
    /// in packets of their own may be filled from several threads at once.
    void fill_leaf(const TriangleMesh& mesh, std::span<const std::uint32_t> triangles, std::uint32_t first) {
        const std::size_t block = packet_floats();
        std::size_t base = static_cast<std::size_t>(first) * block;
        float* bounds = &m_bounds.data[static_cast<std::size_t>(first) * 6];
        for (std::size_t k = 0; k < triangles.size(); k += static_cast<std::size_t>(m_width), base += block) {
            AABB box;
            for (std::size_t lane = 0; lane < static_cast<std::size_t>(m_width); ++lane) {
                const std::uint32_t i = triangles[std::min(k + lane, triangles.size() - 1)];
                fill_lane(mesh, i, &m_data.data[base], lane);
                std::memcpy(&m_data.data[base + static_cast<std::size_t>(m_width * (m_rows - 1)) + lane], &i,
                            sizeof(i));
                for (int c = 0; c < 3; ++c) box.expand(mesh.corner(i, c));
            }
            for (int a = 0; a < 3; ++a) {
                bounds[a] = box.lo[a];
                bounds[3 + a] = box.hi[a];
            }
            bounds += 6;
        }
    }

    std::size_t bytes() const { return (m_data.size + m_bounds.size) * sizeof(float); }
    /// Packet k's box: the corners' smallest x, y, z, then their largest (the packet walk's cull).
    const float* bounds(std::uint32_t k) const { return m_bounds.data.get() + static_cast<std::size_t>(k) * 6; }
    const float* packet(std::uint32_t k) const {
        return m_data.data.get() + static_cast<std::size_t>(k) * packet_floats();
    }
    /// The mesh's triangle in a lane of packet p (a pointer from packet()).
    std::uint32_t original(const float* p, int lane) const {
        std::uint32_t i;
        std::memcpy(&i, p + m_width * (m_rows - 1) + lane, sizeof(i));
        return i;
    }

private:
    std::size_t packet_floats() const { return static_cast<std::size_t>(m_rows) * static_cast<std::size_t>(m_width); }

    void fill_lane(const TriangleMesh& mesh, std::uint32_t i, float* block, std::size_t lane) const {
        const Point3 &p0 = mesh.corner(i, 0), &p1 = mesh.corner(i, 1), &p2 = mesh.corner(i, 2);
        auto row = [&](int r, float x) { block[static_cast<std::size_t>(m_width * r) + lane] = x; };
        if (m_test == TriangleTest::plane) {
            const PlaneTriangle p(p0, p1, p2);
            const float values[13] = {p.normal.x,
                                      p.normal.y,
                                      p.normal.z,
                                      p.offset,
                                      p.p0x,
                                      p.p0y,
                                      p.e1x,
                                      p.e1y,
                                      p.e2x,
                                      p.e2y,
                                      p.inv_det,
                                      static_cast<float>(p.ax),
                                      static_cast<float>(p.ay)};
            for (int r = 0; r < 13; ++r) row(r, values[r]);
            return;
        }
        // Moller-Trumbore computes the edges from the corners first: stored, they are the same floats.
        const Vec3 q1 = m_test == TriangleTest::moller ? p1 - p0 : p1;
        const Vec3 q2 = m_test == TriangleTest::moller ? p2 - p0 : p2;
        for (int a = 0; a < 3; ++a) {
            row(a, p0[a]);
            row(3 + a, q1[a]);
            row(6 + a, q2[a]);
        }
    }

    TriangleTest m_test = TriangleTest::watertight;
    int m_rows = 10;
    int m_width = 4;
    /// Floats allocated without a value (std::vector would zero them).
    struct Floats {
        std::unique_ptr<float[]> data;
        std::size_t size = 0;
        void allocate(std::size_t n) {
            data = std::make_unique_for_overwrite<float[]>(n);
            size = n;
        }
    };
    Floats m_data;
    Floats m_bounds;
};

/// \brief The per-ray constants of a packet test (scalars: each leaf test spreads them over its lanes).
template <TriangleTest Test>
struct PacketRay;

template <>
struct PacketRay<TriangleTest::watertight> {
    const Ray& ray;
    float tmin;
    int kx = 0, ky = 1, kz = 2;
    bool ok;
    float ox = 0, oy = 0, oz = 0, sx = 0, sy = 0, sz = 0;  // origin and shear, already permuted to (kx, ky, kz)
    // The shear of WatertightRay, computed inline (it is per ray); the rare scalar fallback builds the
    // WatertightRay itself, and the tests compare both paths with the scalar test.
    explicit PacketRay(const Ray& r)
        : PacketRay(r, is_finite(r.origin) && is_finite(r.direction) &&
                           (r.direction.x != 0.0f || r.direction.y != 0.0f || r.direction.z != 0.0f)) {}
    /// For a ray already known to have a finite origin and a finite, nonzero direction (usable), or not: the
    /// packet walk checks its lanes together.
    PacketRay(const Ray& r, bool usable) : ray(r), tmin(r.tmin), ok(usable) {
        if (!ok) return;
        const Vec3& d = r.direction;
        kz = max_dimension(glm::abs(d));
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        if (d[kz] < 0.0f) std::swap(kx, ky);
        ox = r.origin[kx];
        oy = r.origin[ky];
        oz = r.origin[kz];
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1.0f / d[kz];
    }
    bool valid() const { return ok; }
};

template <>
struct PacketRay<TriangleTest::moller> {
    const Ray& ray;
    explicit PacketRay(const Ray& r) : ray(r) {}
    PacketRay(const Ray& r, bool) : ray(r) {}
    bool valid() const { return true; }
};

template <>
struct PacketRay<TriangleTest::plane> {
    const Ray& ray;
    explicit PacketRay(const Ray& r) : ray(r) {}
    PacketRay(const Ray& r, bool) : ray(r) {}
    bool valid() const { return true; }
};

/// The watertight lanes whose edge function rounded to zero, by the scalar test (double fallback).
template <int W>
[[gnu::noinline]] int redo_exact(const PacketRay<TriangleTest::watertight>& r, const float* p, float tmax, int redo,
                                 int bits, typename Lanes<W>::F& t, typename Lanes<W>::F& u, typename Lanes<W>::F& v) {
    const WatertightRay sheared(r.ray);
    for (int lane = 0; lane < W; ++lane) {
        if (!((redo >> lane) & 1)) continue;
        const Point3 p0(p[lane], p[W + lane], p[2 * W + lane]);
        const Point3 p1(p[3 * W + lane], p[4 * W + lane], p[5 * W + lane]);
        const Point3 p2(p[6 * W + lane], p[7 * W + lane], p[8 * W + lane]);
        if (const auto h = intersect_watertight(sheared, r.tmin, tmax, p0, p1, p2)) {
            t[lane] = h->t;
            u[lane] = h->u;
            v[lane] = h->v;
            bits |= 1 << lane;
        }
    }
    return bits;
}

/// c[axis] lane by lane, for axis numbers 0, 1, 2 stored as floats (the plane test's kept axes differ per
/// triangle).
template <int W>
[[gnu::always_inline]] inline typename Lanes<W>::F pick_axis(const typename Lanes<W>::F& axis,
                                                             const typename Lanes<W>::F* c) {
    using I = typename Lanes<W>::I;
    const I is0 = axis == splat<W>(0.0f), is1 = axis == splat<W>(1.0f);
    return is0 ? c[0] : (is1 ? c[1] : c[2]);
}

/// The lanes of one packet of W triangles hit within (tmin, tmax): returns their bits, with t, u, v per lane.
template <TriangleTest Test, int W>
[[gnu::always_inline]] inline int test_packet(const PacketRay<Test>& r, const float* p, float tmax,
                                              typename Lanes<W>::F& t, typename Lanes<W>::F& u_out,
                                              typename Lanes<W>::F& v_out) {
    using F = typename Lanes<W>::F;
    using I = typename Lanes<W>::I;
    auto row = [p](int i) { return load_lanes<W>(p + W * i); };
    const F zero = splat<W>(0.0f), one = splat<W>(1.0f);
    if constexpr (Test == TriangleTest::watertight) {
        const int kx = r.kx, ky = r.ky, kz = r.kz;
        const F ox = splat<W>(r.ox), oy = splat<W>(r.oy), oz = splat<W>(r.oz);
        const F sx = splat<W>(r.sx), sy = splat<W>(r.sy), sz = splat<W>(r.sz);
        // a = p0 - origin etc., in the permuted components.
        const F ax0 = row(kx) - ox, ay0 = row(ky) - oy, az0 = row(kz) - oz;
        const F bx0 = row(3 + kx) - ox, by0 = row(3 + ky) - oy, bz0 = row(3 + kz) - oz;
        const F cx0 = row(6 + kx) - ox, cy0 = row(6 + ky) - oy, cz0 = row(6 + kz) - oz;
        const F ax = ax0 - sx * az0, ay = ay0 - sy * az0;
        const F bx = bx0 - sx * bz0, by = by0 - sy * bz0;
        const F cx = cx0 - sx * cz0, cy = cy0 - sy * cz0;
        const F u = cx * by - cy * bx;
        const F v = ax * cy - ay * cx;
        const F w = bx * ay - by * ax;
        const I negative = (u < zero) | (v < zero) | (w < zero);
        const I positive = (u > zero) | (v > zero) | (w > zero);
        // Lanes with an edge function of exactly zero take the scalar path (double-precision recompute).
        const I exact = (u == zero) | (v == zero) | (w == zero);
        int bits = lane_bits(~(negative & positive) & ~exact);
        int redo = lane_bits(exact);
        if (bits) {
            const F det = u + v + w;
            const F t_scaled = u * (sz * az0) + v * (sz * bz0) + w * (sz * cz0);
            const F tmin_lanes = splat<W>(r.tmin), tmax_lanes = splat<W>(tmax);
            const I det_ok = (det != zero) & (abs_lanes<W>(det) < splat<W>(kInfinity));
            const I in_pos = (det > zero) & (t_scaled > tmin_lanes * det) & (t_scaled < tmax_lanes * det);
            const I in_neg = (det < zero) & (t_scaled < tmin_lanes * det) & (t_scaled > tmax_lanes * det);
            bits &= lane_bits(det_ok & (in_pos | in_neg));
            if (bits) {
                const F inv = one / det;
                t = t_scaled * inv;
                bits &= lane_bits((t > tmin_lanes) & (t < tmax_lanes));
                // The scalar test's t error bound (watertight_t_error), on the lanes.
                const auto max_abs = [](F a, F b, F c) {
                    a = abs_lanes<W>(a), b = abs_lanes<W>(b), c = abs_lanes<W>(c);
                    a = a > b ? a : b;
                    return a > c ? a : c;
                };
                const F delta_t =
                    watertight_t_error<F>(max_abs(ax, bx, cx), max_abs(ay, by, cy), max_abs(az0, bz0, cz0),
                                          max_abs(sz * az0, sz * bz0, sz * cz0), max_abs(u, v, w), abs_lanes<W>(inv));
                // Hits within the bound are decided by the scalar test (double-precision t), as it decides them.
                const int near = bits & lane_bits(t <= delta_t);
                bits &= ~near;
                redo |= near;
                u_out = v * inv;
                v_out = w * inv;
            }
        }
        if (redo) [[unlikely]]
            bits = redo_exact<W>(r, p, tmax, redo, bits, t, u_out, v_out);
        return bits;
    } else if constexpr (Test == TriangleTest::moller) {
        const Ray& ray = r.ray;
        const F o[3] = {splat<W>(ray.origin.x), splat<W>(ray.origin.y), splat<W>(ray.origin.z)};
        const F d[3] = {splat<W>(ray.direction.x), splat<W>(ray.direction.y), splat<W>(ray.direction.z)};
        const F p0[3] = {row(0), row(1), row(2)};
        const F e1[3] = {row(3), row(4), row(5)};
        const F e2[3] = {row(6), row(7), row(8)};
        // pvec = cross(d, e2), det = dot(e1, pvec), summed as glm sums: (x + y) + z.
        const F pv[3] = {d[1] * e2[2] - e2[1] * d[2], d[2] * e2[0] - e2[2] * d[0], d[0] * e2[1] - e2[0] * d[1]};
        const F det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
        int bits = lane_bits((det != zero) & (abs_lanes<W>(det) < splat<W>(kInfinity)));
        if (!bits) return 0;
        const F inv = one / det;
        const F tv[3] = {o[0] - p0[0], o[1] - p0[1], o[2] - p0[2]};
        const F u = (tv[0] * pv[0] + tv[1] * pv[1] + tv[2] * pv[2]) * inv;
        bits &= lane_bits((u >= zero) & (u <= one));
        if (!bits) return 0;
        const F qv[3] = {tv[1] * e1[2] - e1[1] * tv[2], tv[2] * e1[0] - e1[2] * tv[0], tv[0] * e1[1] - e1[0] * tv[1]};
        const F v = (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]) * inv;
        bits &= lane_bits((v >= zero) & (u + v <= one));
        if (!bits) return 0;
        t = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) * inv;
        bits &= lane_bits((t > splat<W>(ray.tmin)) & (t < splat<W>(tmax)));
        u_out = u;
        v_out = v;
        return bits;
    } else {
        const Ray& ray = r.ray;
        const F o[3] = {splat<W>(ray.origin.x), splat<W>(ray.origin.y), splat<W>(ray.origin.z)};
        const F d[3] = {splat<W>(ray.direction.x), splat<W>(ray.direction.y), splat<W>(ray.direction.z)};
        const F n[3] = {row(0), row(1), row(2)};
        const F offset = row(3), p0x = row(4), p0y = row(5), e1x = row(6), e1y = row(7), e2x = row(8), e2y = row(9);
        const F inv_det = row(10), axis_x = row(11), axis_y = row(12);
        const F denom = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
        int bits = lane_bits((inv_det != zero) & (denom != zero));
        if (!bits) return 0;
        t = (offset - (n[0] * o[0] + n[1] * o[1] + n[2] * o[2])) / denom;
        bits &= lane_bits((t > splat<W>(ray.tmin)) & (t < splat<W>(tmax)));
        if (!bits) return 0;
        const F px = pick_axis<W>(axis_x, o) + t * pick_axis<W>(axis_x, d) - p0x;
        const F py = pick_axis<W>(axis_y, o) + t * pick_axis<W>(axis_y, d) - p0y;
        const F alpha = (px * e2y - py * e2x) * inv_det;
        const F beta = (e1x * py - e1y * px) * inv_det;
        bits &= lane_bits((alpha >= zero) & (beta >= zero) & (alpha + beta <= one));
        u_out = alpha;
        v_out = beta;
        return bits;
    }
}

/// Asks for every cache line of packets [first, first + count).
[[gnu::always_inline]] inline void prefetch_packets(const TrianglePackets& packets, std::uint32_t first,
                                                    std::uint32_t count) {
    const char* begin = reinterpret_cast<const char*>(packets.packet(first));
    const char* end = reinterpret_cast<const char*>(packets.packet(first + count));
    for (const char* line = begin; line < end; line += 64) __builtin_prefetch(line);
}

// Tried and reverted: bounds per packet. Each leaf's triangles grouped into spatially compact packets
// (median splits along the widest centroid axis), the packets' bounds (8 floats each, an array of their
// own) tested first by a four-lane slab test, and only the packets passed tested, while their entry lay
// before the closest hit. A third of the packets passed (bunny, random rays), and callgrind ran 940 -> 698 /
// 690 -> 565 leaf instructions a ray closest / any-hit, but 4.1 -> 6.6 / 2.3 -> 4.9 mispredicts; against
// these leaves in one process (see kd_walk): 0.93-0.95x closest, 0.88-0.96x any-hit (bunny), 0.92-1.03x /
// 0.96-0.98x (dragon). Asking only for the passed packets' lines, after the bounds test, was slower still.

/// Tests packet k of width W against (tmin, closest): on a hit, true, and for closest-hit the nearest of its
/// hits lowers closest and fills hit (mesh triangle index).
template <TriangleTest Test, bool AnyHit, int W>
[[gnu::always_inline]] inline bool test_one_packet(const TrianglePackets& packets, const PacketRay<Test>& r,
                                                   std::uint32_t k, float& closest, MeshHit& hit) {
    typename Lanes<W>::F t{}, u{}, v{};
    const float* p = packets.packet(k);
    const int bits = test_packet<Test, W>(r, p, closest, t, u, v);
    if (!bits) return false;
    if constexpr (!AnyHit) {
        int best = -1;
        for (int lane = 0; lane < W; ++lane)
            if (((bits >> lane) & 1) && (best < 0 || t[lane] < t[best])) best = lane;
        closest = t[best];
        hit = MeshHit{t[best], packets.original(p, best), u[best], v[best]};
    }
    return true;
}

/// Tests packets [first, first + count) of width W against (tmin, closest). Closest-hit: the nearest hit
/// lowers closest and fills hit (mesh triangle index). AnyHit: true at the first hit.
template <TriangleTest Test, bool AnyHit, int W>
[[gnu::always_inline]] inline bool test_packets(const TrianglePackets& packets, const PacketRay<Test>& r,
                                                std::uint32_t first, std::uint32_t count, float& closest,
                                                MeshHit& hit) {
    // The leaf's packets are one contiguous run, usually not in cache: ask for all of its lines at once
    // rather than one miss after another.
    prefetch_packets(packets, first, count);
    bool any = false;
    for (std::uint32_t k = first; k < first + count; ++k) {
        if (!test_one_packet<Test, AnyHit, W>(packets, r, k, closest, hit)) continue;
        if constexpr (AnyHit) return true;
        any = true;
    }
    return any;
}

#if RTLAB_KD_HAVE_AVX2_LEAVES
/// Packets of 8 with AVX2 (only on CPUs that have it): the packet test above, compiled for AVX2 here.
/// AVX2 without FMA, so every lane still rounds as the scalar test does.
template <TriangleTest Test, bool AnyHit>
[[gnu::target("avx2"), gnu::noinline]] bool test_packets_avx2(const TrianglePackets& packets, const PacketRay<Test>& r,
                                                              std::uint32_t first, std::uint32_t count, float& closest,
                                                              MeshHit& hit) {
    return test_packets<Test, AnyHit, 8>(packets, r, first, count, closest, hit);
}
#endif

}  // namespace rtlab::kd
