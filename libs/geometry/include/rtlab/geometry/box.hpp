#pragma once
/// \brief Solid axis-aligned box.
#include <rtlab/geometry/shape.hpp>

namespace rtlab {

/// \brief Axis-aligned box; the normal is the face's outward axis; uv are the face's two other
/// coordinates scaled to [0, 1].
class Box final : public Shape {
public:
    explicit Box(const AABB& box);
    AABB bounds() const override { return m_box; }
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;

private:
    bool hit_t(const Ray& ray, float& t) const;
    AABB m_box;
};

}  // namespace rtlab
