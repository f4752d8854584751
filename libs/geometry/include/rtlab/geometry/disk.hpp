#pragma once
/// \brief Flat disk: a circle in a plane, or an annulus (a ring such as Saturn's) with an inner radius.
#include <rtlab/geometry/shape.hpp>

namespace rtlab {

/// \brief Disk by centre, unit normal (its outside), radius and inner radius (0: a full disk). uv = (radial
/// fraction (r - inner) / (radius - inner), angle / 2 pi), so u runs from the hole's edge (0) to the rim
/// (1): a ring image stored as a radial strip, inner edge first, is looked up by u alone.
class Disk final : public Shape {
public:
    /// Throws rtlab::Error for a radius that is not positive and finite, an inner radius outside
    /// [0, radius), or a zero normal.
    Disk(const Point3& centre, const Normal3& normal, float radius, float inner_radius = 0.0f);
    AABB bounds() const override;
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;
    // What an area light samples the disk by.
    const Point3& centre() const { return m_centre; }
    const Normal3& normal() const { return m_normal; }
    float radius() const { return m_radius; }
    float inner_radius() const { return m_inner_radius; }
    using Shape::uv_footprint;
    std::optional<UvFootprint> uv_footprint(const Mat4& to_world) const override;

private:
    bool hit_t(const Ray& ray, float& t) const;
    Point3 m_centre;
    Normal3 m_normal;
    float m_radius;
    float m_inner_radius;
};

}  // namespace rtlab
