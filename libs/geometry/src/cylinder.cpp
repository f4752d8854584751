#include <rtlab/core/error.hpp>
#include <rtlab/geometry/cylinder.hpp>

#include "hit_fill.hpp"

namespace rtlab {

Cylinder::Cylinder(const Point3& base, const Point3& top, float radius, bool caps)
    : m_base(base), m_radius(radius), m_caps(caps) {
    const Vec3 axis = top - base;
    m_height = glm::length(axis);
    if (!(m_height > 0.0f) || !std::isfinite(m_height)) throw Error("cylinder: base and top must differ and be finite");
    if (!(radius > 0.0f) || !std::isfinite(radius)) throw Error("cylinder: radius must be positive and finite");
    m_frame = Frame::from_normal(axis / m_height);
}

AABB Cylinder::bounds() const {
    const Vec3 n = m_frame.n;
    const Vec3 e = m_radius * glm::sqrt(glm::max(Vec3(0.0f), Vec3(1.0f) - n * n));
    AABB b{m_base - e, m_base + e};
    b.expand(AABB{m_base + m_height * n - e, m_base + m_height * n + e});
    return b;
}

bool Cylinder::nearest(const Ray& ray, Candidate& best) const {
    const Vec3 o = m_frame.to_local(ray.origin - m_base);
    const Vec3 d = m_frame.to_local(ray.direction);
    best.t = ray.tmax;
    bool found = false;
    auto consider = [&](float t, int part) {
        if (t > ray.tmin && t < best.t) best = {t, part}, found = true;
    };
    const float a = d.x * d.x + d.y * d.y;
    if (a > 0.0f) {
        const float b = o.x * d.x + o.y * d.y;
        const Vec2 perp = Vec2(o.x, o.y) - (b / a) * Vec2(d.x, d.y);
        const float dist = glm::length(perp);
        const float disc = a * (m_radius - dist) * (m_radius + dist);
        const float c = o.x * o.x + o.y * o.y - m_radius * m_radius;
        float t0, t1;
        if (geometry::stable_roots(a, b, c, disc, t0, t1)) {
            for (float t : {t0, t1}) {
                const float z = o.z + t * d.z;
                if (z >= 0.0f && z <= m_height) consider(t, 0);
            }
        }
    }
    if (m_caps && d.z != 0.0f) {
        for (int cap = 1; cap <= 2; ++cap) {
            const float z = cap == 1 ? 0.0f : m_height;
            const float t = (z - o.z) / d.z;
            const float x = o.x + t * d.x, y = o.y + t * d.y;
            if (x * x + y * y <= m_radius * m_radius) consider(t, cap);
        }
    }
    return found;
}

bool Cylinder::intersect(const Ray& ray, SurfaceHit& hit) const {
    Candidate c;
    if (!nearest(ray, c)) return false;
    // The point in the cylinder's frame, put back on the surface: the side's (x, y) scaled to the radius
    // (Pharr et al.: gamma(3) |x|, |y|), a cap's z set to its plane exactly; then back to the world.
    Vec3 local = m_frame.to_local(ray.origin - m_base) + c.t * m_frame.to_local(ray.direction);
    Vec3 local_error(0.0f);
    const float radial = glm::length(Vec2(local.x, local.y));
    if (c.part == 0) {
        if (radial > 0.0f && std::isfinite(radial)) local.x *= m_radius / radial, local.y *= m_radius / radial;
        local.z = std::clamp(local.z, 0.0f, m_height);
        local_error = gamma_bound(3) * Vec3(std::abs(local.x), std::abs(local.y), 0.0f);
    } else {
        local.z = c.part == 1 ? 0.0f : m_height;
    }
    const Point3 p = m_base + m_frame.to_world(local);
    const Vec3 error = geometry::frame_point_error(p, m_frame, local, local_error);
    const float angle = std::atan2(local.y, local.x);
    const float u = (angle < 0.0f ? angle + 2.0f * kPi : angle) / (2.0f * kPi);
    if (c.part == 0) {
        const Normal3 n = glm::normalize(m_frame.to_world(Vec3(local.x, local.y, 0.0f)));
        const Vec3 tangent = m_frame.to_world(Vec3(-local.y, local.x, 0.0f));
        geometry::fill_hit(hit, ray, c.t, p, error, n, {u, local.z / m_height}, tangent, 0, this);
    } else {
        const Normal3 n = c.part == 1 ? -m_frame.n : m_frame.n;
        geometry::fill_hit(hit, ray, c.t, p, error, n, {u, radial / m_radius}, m_frame.s, 0, this);
    }
    return true;
}

bool Cylinder::occluded(const Ray& ray) const {
    Candidate c;
    return nearest(ray, c);
}

}  // namespace rtlab
