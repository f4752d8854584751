#include <rtlab/core/error.hpp>
#include <rtlab/geometry/box.hpp>

#include "hit_fill.hpp"

namespace rtlab {

Box::Box(const AABB& box) : m_box(box) {
    if (box.is_empty() || !is_finite(box.lo) || !is_finite(box.hi))
        throw Error("box: bounds must be finite and non-empty");
}

bool Box::hit_t(const Ray& ray, float& t) const {
    const auto range = m_box.intersect(Ray{ray.origin, ray.direction, -kInfinity, kInfinity});
    if (!range) return false;
    // The entry point, or the exit point for a ray starting inside.
    if (range->min > ray.tmin && range->min < ray.tmax)
        t = range->min;
    else if (range->max > ray.tmin && range->max < ray.tmax)
        t = range->max;
    else
        return false;
    return true;
}

bool Box::intersect(const Ray& ray, SurfaceHit& hit) const {
    float t;
    if (!hit_t(ray, t)) return false;
    Point3 p = ray.at(t);
    // The face is the axis where the point is relatively closest to a slab plane.
    int axis = 0;
    float best = kInfinity;
    bool upper = false;
    const Vec3 ext = m_box.extent();
    for (int a = 0; a < 3; ++a) {
        const float scale = ext[a] > 0.0f ? ext[a] : 1.0f;
        const float dlo = std::abs(p[a] - m_box.lo[a]) / scale, dhi = std::abs(p[a] - m_box.hi[a]) / scale;
        if (dlo < best) best = dlo, axis = a, upper = false;
        if (dhi < best) best = dhi, axis = a, upper = true;
    }
    Normal3 n(0.0f);
    n[axis] = upper ? 1.0f : -1.0f;
    // Snapped onto the face (its plane and its rectangle): the point is then exactly on the box, so its
    // error bound is zero and a spawned ray is offset by one float step.
    p = glm::clamp(p, m_box.lo, m_box.hi);
    p[axis] = upper ? m_box.hi[axis] : m_box.lo[axis];
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const Vec2 uv(ext[a1] > 0.0f ? (p[a1] - m_box.lo[a1]) / ext[a1] : 0.0f,
                  ext[a2] > 0.0f ? (p[a2] - m_box.lo[a2]) / ext[a2] : 0.0f);
    Vec3 tangent(0.0f);
    tangent[a1] = 1.0f;
    geometry::fill_hit(hit, ray, t, p, Vec3(0.0f), n, uv, tangent, 0, this);
    return true;
}

bool Box::occluded(const Ray& ray) const {
    float t;
    return hit_t(ray, t);
}

}  // namespace rtlab
