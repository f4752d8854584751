#include "mesh_triangles.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace rtlab::accel {

namespace {

// A corner of the clipped polygon in double, with the coordinates that are exact floats marked: the
// triangle's own corners, and each cut point's coordinate on the axis of its cut (the box plane itself).
struct Corner {
    double x[3];
    bool exact[3];
};

// The next float below / above f, on the bits (std::nextafter is a library call, and this runs for most
// coordinates of most clipped triangles). f is finite or +-infinity, never NaN.
float next_down(float f) {
    if (f == 0.0f) return -std::numeric_limits<float>::denorm_min();
    if (f == -std::numeric_limits<float>::infinity()) return f;
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0.0f ? bits - 1 : bits + 1);
}
float next_up(float f) { return -next_down(-f); }

float round_down(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) > x ? next_down(f) : f;
}
float round_up(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) < x ? next_up(f) : f;
}

}  // namespace

AABB clip_triangle(const Point3& a, const Point3& b, const Point3& c, const AABB& box) {
    // Computed in double and rounded outward, so that the bounds hold the whole clipped part whatever the
    // rounding: a float clip may round a cut point's other coordinates inward, and a triangle reaching
    // a later split plane by an ulp is then left out of the child that a ray meets it in.
    // A triangle clipped by 6 planes has at most 9 corners.
    // Two buffers used in turn (no copy of the polygon per plane).
    std::array<Corner, 12> buffers[2];
    Corner* poly = buffers[0].data();
    Corner* next = buffers[1].data();
    const Point3* corners[3] = {&a, &b, &c};
    double scale = 0.0;  // bounds the coordinates' magnitude, for the error bound of the cut points
    for (int k = 0; k < 3; ++k)
        for (int axis = 0; axis < 3; ++axis) {
            poly[k].x[axis] = (*corners[k])[axis];
            poly[k].exact[axis] = true;
            scale = std::max(scale, std::abs(poly[k].x[axis]));
        }
    std::size_t n = 3;
    for (int axis = 0; axis < 3 && n > 0; ++axis) {
        for (int side = 0; side < 2 && n > 0; ++side) {
            const double plane = side == 0 ? box.lo[axis] : box.hi[axis];
            auto inside = [&](const Corner& p) { return side == 0 ? p.x[axis] >= plane : p.x[axis] <= plane; };
            // Most planes of a child box do not cut the triangle (only the new split plane does, in a
            // node's straddlers): with every corner inside, the pass below would return the same polygon.
            std::size_t in = 0;
            for (std::size_t i = 0; i < n; ++i) in += inside(poly[i]) ? 1 : 0;
            if (in == n) continue;
            std::size_t m = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const Corner& p = poly[i];
                const Corner& q = poly[i + 1 == n ? 0 : i + 1];
                const bool p_in = inside(p), q_in = inside(q);
                if (p_in) next[m++] = p;
                if (p_in != q_in) {
                    const double t = (plane - p.x[axis]) / (q.x[axis] - p.x[axis]);
                    Corner& x = next[m++];
                    for (int k = 0; k < 3; ++k) {
                        // An edge level in k keeps its coordinate exactly (t * 0 adds nothing).
                        x.x[k] = p.x[k] + t * (q.x[k] - p.x[k]);
                        x.exact[k] = p.exact[k] && q.exact[k] && p.x[k] == q.x[k];
                    }
                    x.x[axis] = plane;  // exactly on the plane, whatever the rounding above
                    x.exact[axis] = true;
                }
            }
            n = m;
            std::swap(poly, next);
        }
    }
    if (n == 0) return AABB{};
    // Cut points of cut points: a few roundings of double each, far below a float's ulp; the bound leaves
    // a wide margin and costs at most one ulp of float outward.
    const double error = 1e-12 * scale;
    AABB out;
    for (int axis = 0; axis < 3; ++axis) {
        float lo = std::numeric_limits<float>::infinity(), hi = -lo;
        for (std::size_t i = 0; i < n; ++i) {
            const Corner& p = poly[i];
            const float l = p.exact[axis] ? static_cast<float>(p.x[axis]) : round_down(p.x[axis] - error);
            const float h = p.exact[axis] ? static_cast<float>(p.x[axis]) : round_up(p.x[axis] + error);
            lo = std::min(lo, l);
            hi = std::max(hi, h);
        }
        out.lo[axis] = lo;
        out.hi[axis] = hi;
    }
    return out.intersected(box);
}

}  // namespace rtlab::accel
