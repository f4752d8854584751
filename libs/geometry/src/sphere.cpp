#include <rtlab/core/error.hpp>
#include <rtlab/geometry/sphere.hpp>

#include "hit_fill.hpp"

#include <string>

namespace rtlab {

Sphere::Sphere(const Point3& centre, float radius) : m_centre(centre), m_radius(radius) {
    if (!(radius > 0.0f) || !std::isfinite(radius) || !is_finite(centre))
        throw Error("sphere: radius must be positive and finite, got " + std::to_string(radius));
}

AABB Sphere::bounds() const { return {m_centre - Vec3(m_radius), m_centre + Vec3(m_radius)}; }

bool Sphere::intersect(const Ray& ray, SurfaceHit& hit) const {
    float t;
    if (!nearest_root(ray, t)) return false;
    complete_hit(ray, t, hit);
    return true;
}

void Sphere::complete_hit(const Ray& ray, float t, SurfaceHit& hit) const { fill(ray, t, hit, true, true); }

void Sphere::complete_hit_without_uv(const Ray& ray, float t, SurfaceHit& hit) const { fill(ray, t, hit, false, true); }

void Sphere::complete_hit_for(const Ray& ray, float t, SurfaceHit& hit, bool with_uv, bool with_tangent) const {
    fill(ray, t, hit, with_uv, with_tangent);
}

inline void Sphere::fill(const Ray& ray, float t, SurfaceHit& hit, bool with_uv, bool with_tangent) const {
    // Relative to the centre, then projected back onto the sphere (Pharr et al., pbrt-v4): the projection
    // removes the radial error of o + t d, which is what a spawned ray must clear, leaving gamma(5) |rel|.
    Vec3 rel = (ray.origin - m_centre) + t * ray.direction;
    const float len = glm::length(rel);
    // A sphere below the float spacing at its centre can put the rounded point on the centre itself.
    if (!(len > 0.0f) || !std::isfinite(len))
        rel = -glm::normalize(ray.direction) * m_radius;
    else
        rel *= m_radius / len;
    const Point3 p = m_centre + rel;
    const Vec3 error = gamma_bound(5) * glm::abs(rel) + gamma_bound(1) * glm::abs(p);
    const Normal3 n = glm::normalize(rel);
    Vec2 uv(0.0f);
    if (with_uv) {
        const float phi = std::atan2(-n.z, n.x);  // eastwards from -x
        uv.x = (phi + kPi) / (2.0f * kPi);
        uv.y = 1.0f - std::acos(std::clamp(n.y, -1.0f, 1.0f)) / kPi;
    }
    const Vec3 tangent = with_tangent ? geometry::unit_tangent(Vec3(n.z, 0.0f, -n.x), n) : hit.tangent;
    geometry::fill_hit_unit_tangent(hit, ray, t, p, error, n, uv, tangent, 0, this);
}

std::optional<UvFootprint> Sphere::uv_footprint(const Mat4& to_world) const {
    return sphere_footprint(to_world, m_centre, m_radius);
}

}  // namespace rtlab
