#include <rtlab/core/error.hpp>
#include <rtlab/core/frame.hpp>
#include <rtlab/geometry/disk.hpp>

#include "hit_fill.hpp"

#include <algorithm>

namespace rtlab {

Disk::Disk(const Point3& centre, const Normal3& normal, float radius, float inner_radius)
    : m_centre(centre), m_radius(radius), m_inner_radius(inner_radius) {
    if (!(radius > 0.0f) || !std::isfinite(radius)) throw Error("disk: radius must be positive and finite");
    if (!(inner_radius >= 0.0f && inner_radius < radius)) throw Error("disk: inner radius must be in [0, radius)");
    if (!(glm::length(normal) > 0.0f) || !is_finite(normal)) throw Error("disk: normal must be non-zero and finite");
    m_normal = glm::normalize(normal);
}

AABB Disk::bounds() const {
    // Extent along each axis: r sqrt(1 - n_a^2).
    const Vec3 e = m_radius * glm::sqrt(glm::max(Vec3(0.0f), Vec3(1.0f) - m_normal * m_normal));
    return {m_centre - e, m_centre + e};
}

bool Disk::hit_t(const Ray& ray, float& t) const {
    const float denom = glm::dot(m_normal, ray.direction);
    if (denom == 0.0f || !std::isfinite(denom)) return false;
    t = glm::dot(m_normal, m_centre - ray.origin) / denom;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    const Vec3 r = ray.at(t) - m_centre;
    const float r2 = glm::dot(r, r);
    // The hole's edge belongs to the ring, as the rim does: both bounds closed.
    return r2 <= m_radius * m_radius && r2 >= m_inner_radius * m_inner_radius;
}

bool Disk::intersect(const Ray& ray, SurfaceHit& hit) const {
    float t;
    if (!hit_t(ray, t)) return false;
    // In the disk's frame with z set to the plane exactly, then back to the world.
    const Frame f = Frame::from_normal(m_normal);
    Vec3 local = f.to_local(ray.origin - m_centre) + t * f.to_local(ray.direction);
    local.z = 0.0f;
    const Point3 p = m_centre + f.to_world(local);
    const Vec3 error = geometry::frame_point_error(p, f, local, Vec3(0.0f));
    const float angle = std::atan2(local.y, local.x);
    const float radial = (glm::length(Vec2(local.x, local.y)) - m_inner_radius) / (m_radius - m_inner_radius);
    const Vec2 uv(std::clamp(radial, 0.0f, 1.0f), (angle < 0.0f ? angle + 2.0f * kPi : angle) / (2.0f * kPi));
    geometry::fill_hit(hit, ray, t, p, error, m_normal, uv, f.s, 0, this);
    return true;
}

bool Disk::occluded(const Ray& ray) const {
    float t;
    return hit_t(ray, t);
}

std::optional<UvFootprint> Disk::uv_footprint(const Mat4& to_world) const {
    return disk_footprint(to_world, m_centre, m_radius, m_inner_radius);
}

}  // namespace rtlab
