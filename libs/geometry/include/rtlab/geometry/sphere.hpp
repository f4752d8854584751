#pragma once
/// \brief Sphere, intersected with a cancellation-free quadratic.
#include <rtlab/geometry/quadratic.hpp>
#include <rtlab/geometry/shape.hpp>

namespace rtlab {

/// \brief Sphere by centre and radius. uv: u = longitude (0 at -x, increasing towards -z, i.e. eastwards
/// seen from +y), v = 1 at the north pole (+y) and 0 at the south pole, so an equirectangular planet map
/// whose first row is the north pole appears upright (textures take v = 0 as the image's bottom row).
class Sphere final : public Shape {
public:
    Sphere(const Point3& centre, float radius);
    AABB bounds() const override;
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    // The two tests a scene's list runs on every sphere for every ray are inline, so that a caller holding a
    // Sphere (the render library's lists) runs them without a call.
    bool occluded(const Ray& ray) const override {
        float t;
        return nearest_root(ray, t);
    }
    bool defers_record() const override { return true; }
    bool intersect_distance(const Ray& ray, float& t) const override { return nearest_root(ray, t); }
    void complete_hit(const Ray& ray, float t, SurfaceHit& hit) const override;
    void complete_hit_without_uv(const Ray& ray, float t, SurfaceHit& hit) const override;

private:
    bool nearest_root(const Ray& ray, float& t) const;
    void fill(const Ray& ray, float t, SurfaceHit& hit, bool with_uv) const;
    Point3 m_centre;
    float m_radius;
};

inline bool Sphere::nearest_root(const Ray& ray, float& t) const {
    const Vec3 oc = ray.origin - m_centre;
    const Vec3& d = ray.direction;
    const float a = glm::dot(d, d);
    const float b = glm::dot(oc, d);
    const float c = glm::dot(oc, oc) - m_radius * m_radius;
    // Starting outside and moving away: both roots are negative as stable_roots() rounds them (q < 0, so
    // c / q and q / a are <= 0), which no tmin >= 0 admits; the test costs two compares of numbers the roots need
    // anyway.
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

}  // namespace rtlab
