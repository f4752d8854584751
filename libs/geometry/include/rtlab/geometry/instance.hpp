#pragma once
/// \brief A shape placed by an affine transform, so one mesh or shape can appear several times.
#include <rtlab/geometry/shape.hpp>

#include <memory>

namespace rtlab {

/// \brief object-to-world affine transform applied to a shared shape. Rays go to object space (t is
/// unchanged because the direction is transformed, not normalised); normals come back by the inverse
/// transpose, so non-uniform scales keep them perpendicular. A hit reports the Instance as its shape, the
/// inner point transformed (with its error bound carried through) and the inner object point.
class Instance final : public Shape {
public:
    /// Throws rtlab::Error for a singular or non-finite transform.
    Instance(std::shared_ptr<const Shape> shape, const Mat4& object_to_world);
    AABB bounds() const override;
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;
    // What an area light over an instance samples: the inner shape placed by the matrix.
    const Shape& shape() const { return *m_shape; }
    const Mat4& to_world() const { return m_to_world; }
    using Shape::uv_footprint;
    std::optional<UvFootprint> uv_footprint(const Mat4& to_world) const override;

    /// intersect() in two steps, for a caller that traces the inner shape itself (a scene's packets of rays): the
    /// ray the inner shape is asked about, and the hit record made from the inner shape's hit `local` for it.
    Ray to_object(const Ray& ray) const;
    void finish_hit(const Ray& ray, const SurfaceHit& local, SurfaceHit& hit) const;
    /// True when the ray passes clear of the inner shape's bounds in world space (then intersect() and occluded()
    /// answer no), for a caller that traces the inner shape itself: no transform, no virtual call, no record copy
    /// (a ray missing the bunny's box took about 330 instructions to find out).
    bool misses_bounds(const Ray& ray) const;

private:
    std::shared_ptr<const Shape> m_shape;
    Mat4 m_to_world, m_to_object;
    Mat3 m_normal_to_world;  // inverse transpose of the linear part
    // For the error bound: absolute values of both transforms, and of the float inverse's residual
    // (inverse * transform - identity), which moves every ray a spawned origin sends back to object space.
    Mat3 m_abs_linear, m_abs_inverse_linear, m_abs_residual_linear;
    Vec3 m_abs_translation, m_abs_inverse_translation, m_abs_residual_translation;
    // For misses_bounds(): the world box and how far outside it a hit of the inner shape can lie through the
    // rounding of both transforms: m_guard_absolute + m_guard_relative * 2 |origin| (max norms); no guard for
    // ill-conditioned transforms or unbounded shapes.
    AABB m_world_bounds;
    float m_guard_relative = 0.0f, m_guard_absolute = 0.0f;
    bool m_guard = false;
};

}  // namespace rtlab
