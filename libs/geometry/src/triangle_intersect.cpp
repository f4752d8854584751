#include <rtlab/core/error.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>

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
        case TriangleTest::watertight: return "watertight";
        case TriangleTest::moller: return "moller";
        case TriangleTest::plane: return "plane";
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
