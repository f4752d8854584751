#include <rtlab/core/error.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>

#include <cmath>
#include <string>

namespace rtlab {

TriangleTest parse_triangle_test(std::string_view name) {
    if (name == "watertight") return TriangleTest::watertight;
    if (name == "moller") return TriangleTest::moller;
    if (name == "plane") return TriangleTest::plane;
    throw Error("unknown triangle test '" + std::string(name) + "'; known: watertight, moller, plane");
}

std::string_view to_string(TriangleTest test) {
    switch (test) {
        case TriangleTest::watertight:
            return "watertight";
        case TriangleTest::moller:
            return "moller";
        case TriangleTest::plane:
            return "plane";
    }
    return "?";
}

WatertightRay::WatertightRay(const Ray& ray) : origin(ray.origin) {
    const Vec3& d = ray.direction;
    valid = is_finite(ray.origin) && is_finite(d) && (d.x != 0.0f || d.y != 0.0f || d.z != 0.0f);
    if (!valid) return;
    kz = max_dimension(glm::abs(d));
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0.0f) std::swap(kx, ky);  // keeps the winding, so the sign test needs no per-ray flip
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0f / d[kz];
}

bool watertight_near_hit_in_front(const WatertightRay& r, const Point3& p0, const Point3& p1, const Point3& p2) {
    using D = double;
    // The differences of floats are exact in double for all but far-apart exponents; the shear (sx, sy, sz)
    // defines the ray the float test intersects, so it is taken as exact here too.
    auto shear = [&r](const Point3& p, D& x, D& y, D& z, D& z_world) {
        const D px = D(p[r.kx]) - D(r.origin[r.kx]), py = D(p[r.ky]) - D(r.origin[r.ky]);
        z_world = D(p[r.kz]) - D(r.origin[r.kz]);
        x = px - D(r.sx) * z_world;
        y = py - D(r.sy) * z_world;
        z = D(r.sz) * z_world;
    };
    D ax, ay, az, aw, bx, by, bz, bw, cx, cy, cz, cw;
    shear(p0, ax, ay, az, aw);
    shear(p1, bx, by, bz, bw);
    shear(p2, cx, cy, cz, cw);
    const D u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    const D det = u + v + w;
    if (det == 0.0) return false;
    const D t = (u * az + v * bz + w * cz) / det;
    auto max_abs = [](D x, D y, D z) { return std::fmax(std::fabs(x), std::fmax(std::fabs(y), std::fabs(z))); };
    // watertight_t_error's expression with double's gamma(n) = n eps / (1 - n eps), eps = 2^-53 (one more
    // rounding, of the exact differences above, is absorbed by the factor 3 there).
    constexpr D eps = 0x1p-53;
    auto gamma = [](int n) { return n * eps / (1.0 - n * eps); };
    const D max_x = max_abs(ax, bx, cx), max_y = max_abs(ay, by, cy), max_zw = max_abs(aw, bw, cw);
    const D max_z = max_abs(az, bz, cz), max_e = max_abs(u, v, w);
    const D delta_z = gamma(3) * max_z;
    const D delta_x = gamma(5) * (max_x + max_zw), delta_y = gamma(5) * (max_y + max_zw);
    const D delta_e = 2.0 * (gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    const D delta_t = 3.0 * (gamma(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) / std::fabs(det);
    return t > delta_t;
}

PlaneTriangle::PlaneTriangle(const Point3& p0, const Point3& p1, const Point3& p2) {
    const Vec3 e1 = p1 - p0, e2 = p2 - p0;
    normal = glm::cross(e1, e2);
    offset = glm::dot(normal, p0);
    // Keep the two axes where the triangle's projection is largest: the dominant normal axis is dropped.
    const int drop = max_dimension(glm::abs(normal));
    ax = (drop + 1) % 3;
    ay = (drop + 2) % 3;
    p0x = p0[ax];
    p0y = p0[ay];
    e1x = e1[ax];
    e1y = e1[ay];
    e2x = e2[ax];
    e2y = e2[ay];
    const float det = e1x * e2y - e1y * e2x;
    inv_det = (det != 0.0f && std::isfinite(det) && is_finite(normal)) ? 1.0f / det : 0.0f;
}

}  // namespace rtlab
