#include <rtlab/geometry/uv_footprint.hpp>

#include <algorithm>

namespace rtlab {

namespace {
float largest_axis_scale(const Mat4& m) {
    return std::max({glm::length(Vec3(m[0])), glm::length(Vec3(m[1])), glm::length(Vec3(m[2]))});
}
}  // namespace

UvFootprint sphere_footprint(const Mat4& to_world, const Point3& centre, float radius) {
    const float r = radius * largest_axis_scale(to_world);
    return {Point3(to_world * Vec4(centre, 1.0f)), r, 2.0f * kPi * r};
}

UvFootprint disk_footprint(const Mat4& to_world, const Point3& centre, float radius, float inner_radius) {
    const float scale = largest_axis_scale(to_world);
    return {Point3(to_world * Vec4(centre, 1.0f)), radius * scale, (radius - inner_radius) * scale};
}

}  // namespace rtlab
