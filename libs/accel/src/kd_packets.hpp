#pragma once
// A kd-tree's leaves laid out for one triangle test: each leaf's triangles in packets of four, one
// structure-of-arrays block per packet, tested four at a time. The arithmetic of every lane is the scalar
// test's own, operation for operation (no fused multiply-add on the baseline x86-64 target), so a packet
// answers exactly as the scalar tests of triangle_intersect.hpp do -- the watertight test's
// double-precision fallback included, which runs for the rare lane whose edge function rounds to zero.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <cstdint>
#include <algorithm>
#include <cstring>
#include <span>
#include <vector>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace rtlab::kd {

using F4 = float __attribute__((vector_size(16)));
using I4 = std::int32_t __attribute__((vector_size(16)));

inline F4 splat(float x) { return F4{x, x, x, x}; }
/// Bit i set when lane i of the mask is true (all bits of the lane set).
inline int lane_bits(I4 mask) {
#if defined(__SSE__)
    return _mm_movemask_ps(reinterpret_cast<__m128>(mask));
#else
    return (mask[0] ? 1 : 0) | (mask[1] ? 2 : 0) | (mask[2] ? 4 : 0) | (mask[3] ? 8 : 0);
#endif
}
inline F4 abs4(F4 x) { return reinterpret_cast<F4>(reinterpret_cast<I4>(x) & 0x7FFFFFFF); }

/// Rows of four 32-bit lanes in one packet: corners for watertight, p0 and both edges for
/// Moller-Trumbore, the plane data (its two axis numbers stored as floats) for the plane test; then the
/// mesh's triangle indices, in the cache line that the last data row has already brought in.
constexpr int packet_rows(TriangleTest test) { return test == TriangleTest::plane ? 14 : 10; }

/// \brief Packets of four triangles for one triangle test. Packet k holds rows x 4 floats; a leaf whose
/// count is not a multiple of four repeats its last triangle (a repeated triangle cannot change a hit).
class TrianglePackets {
public:
    TrianglePackets() = default;
    explicit TrianglePackets(TriangleTest test) : m_test(test), m_rows(packet_rows(test)) {}

    TriangleTest test() const { return m_test; }
    /// Appends a leaf's triangles (mesh indices); returns the index of its first packet.
    std::uint32_t add_leaf(const TriangleMesh& mesh, std::span<const std::uint32_t> triangles) {
        const auto first = static_cast<std::uint32_t>(m_data.size() / (4 * static_cast<std::size_t>(m_rows)));
        for (std::size_t k = 0; k < triangles.size(); k += 4) {
            const std::size_t base = m_data.size();
            m_data.resize(base + static_cast<std::size_t>(m_rows) * 4);
            for (std::size_t lane = 0; lane < 4; ++lane) {
                const std::uint32_t i = triangles[std::min(k + lane, triangles.size() - 1)];
                fill_lane(mesh, i, &m_data[base], lane);
                std::memcpy(&m_data[base + 4 * static_cast<std::size_t>(m_rows - 1) + lane], &i, sizeof(i));
            }
        }
        return first;
    }
    std::size_t bytes() const { return m_data.size() * sizeof(float); }
    const float* packet(std::uint32_t k) const { return m_data.data() + static_cast<std::size_t>(k) * m_rows * 4; }
    /// The mesh's triangle in a lane of packet p (a pointer from packet()).
    std::uint32_t original(const float* p, int lane) const {
        std::uint32_t i;
        std::memcpy(&i, p + 4 * (m_rows - 1) + lane, sizeof(i));
        return i;
    }
    void shrink() { m_data.shrink_to_fit(); }

private:
    void fill_lane(const TriangleMesh& mesh, std::uint32_t i, float* block, std::size_t lane) const {
        const Point3 &p0 = mesh.corner(i, 0), &p1 = mesh.corner(i, 1), &p2 = mesh.corner(i, 2);
        auto row = [&](int r, float x) { block[4 * r + lane] = x; };
        if (m_test == TriangleTest::plane) {
            const PlaneTriangle p(p0, p1, p2);
            const float values[13] = {p.normal.x, p.normal.y, p.normal.z, p.offset, p.p0x, p.p0y, p.e1x, p.e1y,
                                      p.e2x, p.e2y, p.inv_det, static_cast<float>(p.ax), static_cast<float>(p.ay)};
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
    int m_rows = 9;
    std::vector<float> m_data;
};

/// \brief The per-ray constants of a packet test.
template <TriangleTest Test>
struct PacketRay;

template <>
struct PacketRay<TriangleTest::watertight> {
    const Ray& ray;
    float tmin;
    int kx = 0, ky = 1, kz = 2;
    bool ok;
    F4 ox, oy, oz, sx, sy, sz;  // origin and shear, already permuted to (kx, ky, kz)
    // The shear of WatertightRay, computed inline (it is per ray); the rare scalar fallback builds the
    // WatertightRay itself, and the tests compare both paths with the scalar test.
    explicit PacketRay(const Ray& r) : ray(r), tmin(r.tmin) {
        const Vec3& d = r.direction;
        ok = is_finite(r.origin) && is_finite(d) && (d.x != 0.0f || d.y != 0.0f || d.z != 0.0f);
        if (!ok) return;
        kz = max_dimension(glm::abs(d));
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        if (d[kz] < 0.0f) std::swap(kx, ky);
        ox = splat(r.origin[kx]);
        oy = splat(r.origin[ky]);
        oz = splat(r.origin[kz]);
        sx = splat(d[kx] / d[kz]);
        sy = splat(d[ky] / d[kz]);
        sz = splat(1.0f / d[kz]);
    }
    bool valid() const { return ok; }
};

template <>
struct PacketRay<TriangleTest::moller> {
    const Ray& ray;
    F4 o[3], d[3];
    explicit PacketRay(const Ray& r) : ray(r) {
        for (int a = 0; a < 3; ++a) {
            o[a] = splat(r.origin[a]);
            d[a] = splat(r.direction[a]);
        }
    }
    bool valid() const { return true; }
};

template <>
struct PacketRay<TriangleTest::plane> {
    const Ray& ray;
    F4 o[3], d[3];
    explicit PacketRay(const Ray& r) : ray(r) {
        for (int a = 0; a < 3; ++a) {
            o[a] = splat(r.origin[a]);
            d[a] = splat(r.direction[a]);
        }
    }
    bool valid() const { return true; }
};

/// The watertight lanes whose edge function rounded to zero, by the scalar test (double fallback).
[[gnu::noinline]] inline int redo_exact(const PacketRay<TriangleTest::watertight>& r, const float* p, float tmax,
                                        int redo, int bits, F4& t, F4& u, F4& v) {
    const WatertightRay sheared(r.ray);
    for (int lane = 0; lane < 4; ++lane) {
        if (!((redo >> lane) & 1)) continue;
        const Point3 p0(p[lane], p[4 + lane], p[8 + lane]);
        const Point3 p1(p[12 + lane], p[16 + lane], p[20 + lane]);
        const Point3 p2(p[24 + lane], p[28 + lane], p[32 + lane]);
        if (const auto h = intersect_watertight(sheared, r.tmin, tmax, p0, p1, p2)) {
            t[lane] = h->t;
            u[lane] = h->u;
            v[lane] = h->v;
            bits |= 1 << lane;
        }
    }
    return bits;
}

/// The lanes of one packet hit within (tmin, tmax): returns their bits, with t, u, v per lane.
template <TriangleTest Test>
[[gnu::always_inline]] inline int test_packet(const PacketRay<Test>& r, const float* p, float tmax, F4& t, F4& u_out, F4& v_out) {
    auto row = [p](int i) {
        F4 x;
        std::memcpy(&x, p + 4 * i, sizeof(F4));
        return x;
    };
    if constexpr (Test == TriangleTest::watertight) {
        const int kx = r.kx, ky = r.ky, kz = r.kz;
        // a = p0 - origin etc., in the permuted components.
        const F4 ax0 = row(kx) - r.ox, ay0 = row(ky) - r.oy, az0 = row(kz) - r.oz;
        const F4 bx0 = row(3 + kx) - r.ox, by0 = row(3 + ky) - r.oy, bz0 = row(3 + kz) - r.oz;
        const F4 cx0 = row(6 + kx) - r.ox, cy0 = row(6 + ky) - r.oy, cz0 = row(6 + kz) - r.oz;
        const F4 ax = ax0 - r.sx * az0, ay = ay0 - r.sy * az0;
        const F4 bx = bx0 - r.sx * bz0, by = by0 - r.sy * bz0;
        const F4 cx = cx0 - r.sx * cz0, cy = cy0 - r.sy * cz0;
        const F4 u = cx * by - cy * bx;
        const F4 v = ax * cy - ay * cx;
        const F4 w = bx * ay - by * ax;
        const F4 zero = splat(0.0f);
        const I4 negative = (u < zero) | (v < zero) | (w < zero);
        const I4 positive = (u > zero) | (v > zero) | (w > zero);
        // Lanes with an edge function of exactly zero take the scalar path (double-precision recompute).
        const I4 exact = (u == zero) | (v == zero) | (w == zero);
        int bits = lane_bits(~(negative & positive) & ~exact);
        const int redo = lane_bits(exact);
        if (bits) {
            const F4 det = u + v + w;
            const F4 t_scaled = u * (r.sz * az0) + v * (r.sz * bz0) + w * (r.sz * cz0);
            const F4 tmin4 = splat(r.tmin), tmax4 = splat(tmax);
            const I4 det_ok = (det != zero) & (abs4(det) < splat(kInfinity));
            const I4 in_pos = (det > zero) & (t_scaled > tmin4 * det) & (t_scaled < tmax4 * det);
            const I4 in_neg = (det < zero) & (t_scaled < tmin4 * det) & (t_scaled > tmax4 * det);
            bits &= lane_bits(det_ok & (in_pos | in_neg));
            if (bits) {
                const F4 inv = splat(1.0f) / det;
                t = t_scaled * inv;
                bits &= lane_bits((t > tmin4) & (t < tmax4));
                u_out = v * inv;
                v_out = w * inv;
            }
        }
        if (redo) [[unlikely]] bits = redo_exact(r, p, tmax, redo, bits, t, u_out, v_out);
        return bits;
    } else if constexpr (Test == TriangleTest::moller) {
        const F4 p0[3] = {row(0), row(1), row(2)};
        const F4 e1[3] = {row(3), row(4), row(5)};
        const F4 e2[3] = {row(6), row(7), row(8)};
        const F4* d = r.d;
        // pvec = cross(d, e2), det = dot(e1, pvec), summed as glm sums: (x + y) + z.
        const F4 pv[3] = {d[1] * e2[2] - e2[1] * d[2], d[2] * e2[0] - e2[2] * d[0], d[0] * e2[1] - e2[0] * d[1]};
        const F4 det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
        const F4 zero = splat(0.0f), one = splat(1.0f);
        int bits = lane_bits((det != zero) & (abs4(det) < splat(kInfinity)));
        if (!bits) return 0;
        const F4 inv = one / det;
        const F4 tv[3] = {r.o[0] - p0[0], r.o[1] - p0[1], r.o[2] - p0[2]};
        const F4 u = (tv[0] * pv[0] + tv[1] * pv[1] + tv[2] * pv[2]) * inv;
        bits &= lane_bits((u >= zero) & (u <= one));
        if (!bits) return 0;
        const F4 qv[3] = {tv[1] * e1[2] - e1[1] * tv[2], tv[2] * e1[0] - e1[2] * tv[0], tv[0] * e1[1] - e1[0] * tv[1]};
        const F4 v = (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]) * inv;
        bits &= lane_bits((v >= zero) & (u + v <= one));
        if (!bits) return 0;
        t = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) * inv;
        bits &= lane_bits((t > splat(r.ray.tmin)) & (t < splat(tmax)));
        u_out = u;
        v_out = v;
        return bits;
    } else {
        const F4 n[3] = {row(0), row(1), row(2)};
        const F4 offset = row(3), p0x = row(4), p0y = row(5), e1x = row(6), e1y = row(7), e2x = row(8), e2y = row(9);
        const F4 inv_det = row(10), axis_x = row(11), axis_y = row(12);
        const F4 zero = splat(0.0f), one = splat(1.0f);
        const F4 denom = n[0] * r.d[0] + n[1] * r.d[1] + n[2] * r.d[2];
        int bits = lane_bits((inv_det != zero) & (denom != zero));
        if (!bits) return 0;
        t = (offset - (n[0] * r.o[0] + n[1] * r.o[1] + n[2] * r.o[2])) / denom;
        bits &= lane_bits((t > splat(r.ray.tmin)) & (t < splat(tmax)));
        if (!bits) return 0;
        // The two kept axes differ per triangle: select the ray's components lane by lane.
        auto pick = [zero](F4 axis, const F4* v) {
            const I4 is0 = axis == zero, is1 = axis == splat(1.0f);
            return is0 ? v[0] : (is1 ? v[1] : v[2]);
        };
        const F4 px = pick(axis_x, r.o) + t * pick(axis_x, r.d) - p0x;
        const F4 py = pick(axis_y, r.o) + t * pick(axis_y, r.d) - p0y;
        const F4 alpha = (px * e2y - py * e2x) * inv_det;
        const F4 beta = (e1x * py - e1y * px) * inv_det;
        bits &= lane_bits((alpha >= zero) & (beta >= zero) & (alpha + beta <= one));
        u_out = alpha;
        v_out = beta;
        return bits;
    }
}

/// Tests packets [first, first + count) against (tmin, closest). Closest-hit: the nearest hit lowers
/// closest and fills hit (mesh triangle index). AnyHit: true at the first hit.
template <TriangleTest Test, bool AnyHit>
inline bool test_packets(const TrianglePackets& packets, const PacketRay<Test>& r, std::uint32_t first,
                         std::uint32_t count, float& closest, MeshHit& hit) {
    // The leaf's packets are one contiguous run, usually not in cache: ask for all of its lines at once
    // rather than one miss after another.
    const char* begin = reinterpret_cast<const char*>(packets.packet(first));
    const char* end = reinterpret_cast<const char*>(packets.packet(first + count));
    for (const char* line = begin; line < end; line += 64) __builtin_prefetch(line);
    bool any = false;
    for (std::uint32_t k = first; k < first + count; ++k) {
        F4 t{}, u{}, v{};
        const float* p = packets.packet(k);
        int bits = test_packet<Test>(r, p, closest, t, u, v);
        if (!bits) continue;
        if constexpr (AnyHit) return true;
        int best = -1;
        for (int lane = 0; lane < 4; ++lane)
            if (((bits >> lane) & 1) && (best < 0 || t[lane] < t[best])) best = lane;
        closest = t[best];
        hit = MeshHit{t[best], packets.original(p, best), u[best], v[best]};
        any = true;
    }
    return any;
}

}  // namespace rtlab::kd
