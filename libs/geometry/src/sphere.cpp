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

// Inline: every sphere of a scene's list runs it once per ray, and the call cost a tenth of the test.
inline bool Sphere::nearest_root(const Ray& ray, float& t) const {
    const Vec3 oc = ray.origin - m_centre;
    const Vec3& d = ray.direction;
    const float a = glm::dot(d, d);
    const float b = glm::dot(oc, d);
    const float c = glm::dot(oc, oc) - m_radius * m_radius;
    // Starting outside and moving away: both roots are negative as stable_roots() rounds them (q < 0, so
    // c / q and q / a are <= 0), which no tmin >= 0 admits. Most rays of a scene pass most spheres so.
    if (b > 0.0f && c > 0.0f && ray.tmin >= 0.0f) return false;
    // |oc|^2 - b^2 / a loses everything for a far ray; the perpendicular vector keeps full precision.
    const Vec3 perp = oc - (b / a) * d;
    const float disc = a * (m_radius - glm::length(perp)) * (m_radius + glm::length(perp));
    float t0, t1;
    if (!geometry::stable_roots(a, b, c, disc, t0, t1)) return false;
    if (t0 > ray.tmin && t0 < ray.tmax)
        t = t0;
    else if (t1 > ray.tmin && t1 < ray.tmax)
        t = t1;
    else
        return false;
    return true;
}

bool Sphere::intersect(const Ray& ray, SurfaceHit& hit) const {
    float t;
    if (!nearest_root(ray, t)) return false;
    complete_hit(ray, t, hit);
    return true;
}

bool Sphere::intersect_distance(const Ray& ray, float& t) const { return nearest_root(ray, t); }

void Sphere::complete_hit(const Ray& ray, float t, SurfaceHit& hit) const { fill(ray, t, hit, true); }

void Sphere::complete_hit_without_uv(const Ray& ray, float t, SurfaceHit& hit) const { fill(ray, t, hit, false); }

inline void Sphere::fill(const Ray& ray, float t, SurfaceHit& hit, bool with_uv) const {
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
    geometry::fill_hit(hit, ray, t, p, error, n, uv, Vec3(n.z, 0.0f, -n.x), 0, this);
}

bool Sphere::occluded(const Ray& ray) const {
    float t;
    return nearest_root(ray, t);
}

}  // namespace rtlab
