#pragma once
/// \brief Sphere, intersected with a cancellation-free quadratic.
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
    bool occluded(const Ray& ray) const override;
    bool defers_record() const override { return true; }
    bool intersect_distance(const Ray& ray, float& t) const override;
    void complete_hit(const Ray& ray, float t, SurfaceHit& hit) const override;
    void complete_hit_without_uv(const Ray& ray, float t, SurfaceHit& hit) const override;

private:
    bool nearest_root(const Ray& ray, float& t) const;
    void fill(const Ray& ray, float t, SurfaceHit& hit, bool with_uv) const;
    Point3 m_centre;
    float m_radius;
};

}  // namespace rtlab
