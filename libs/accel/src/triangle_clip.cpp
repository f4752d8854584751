#include "mesh_triangles.hpp"

#include <array>

namespace rtlab::accel {

AABB clip_triangle(const Point3& a, const Point3& b, const Point3& c, const AABB& box) {
    // A triangle clipped by 6 planes has at most 9 corners.
    std::array<Point3, 12> poly{a, b, c}, next{};
    std::size_t n = 3;
    for (int axis = 0; axis < 3 && n > 0; ++axis) {
        for (int side = 0; side < 2 && n > 0; ++side) {
            const float plane = side == 0 ? box.lo[axis] : box.hi[axis];
            auto inside = [&](const Point3& p) { return side == 0 ? p[axis] >= plane : p[axis] <= plane; };
            std::size_t m = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const Point3& p = poly[i];
                const Point3& q = poly[(i + 1) % n];
                const bool p_in = inside(p), q_in = inside(q);
                if (p_in) next[m++] = p;
                if (p_in != q_in) {
                    const float t = (plane - p[axis]) / (q[axis] - p[axis]);
                    Point3 x = p + t * (q - p);
                    x[axis] = plane;  // exactly on the plane, whatever the rounding above
                    next[m++] = x;
                }
            }
            n = m;
            poly = next;
        }
    }
    AABB out;
    for (std::size_t i = 0; i < n; ++i) out.expand(poly[i]);
    return out.intersected(box);
}

}  // namespace rtlab::accel
