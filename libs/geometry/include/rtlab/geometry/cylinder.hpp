#pragma once
/// \brief Finite cylinder along any axis, with optional end caps.
#include <rtlab/core/frame.hpp>
#include <rtlab/geometry/shape.hpp>

namespace rtlab {

/// \brief Cylinder from base to top with a radius; uv on the side = (angle / 2 pi, height fraction); the
/// caps, when present, are disks facing away from the body. Without caps the tube is open.
class Cylinder final : public Shape {
public:
    Cylinder(const Point3& base, const Point3& top, float radius, bool caps = true);
    AABB bounds() const override;
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;

private:
    struct Candidate {
        float t;
        int part;  // 0 side, 1 base cap, 2 top cap
    };
    bool nearest(const Ray& ray, Candidate& best) const;

    Point3 m_base;
    float m_height;
    float m_radius;
    bool m_caps;
    Frame m_frame;  // n = axis direction
};

}  // namespace rtlab
