#pragma once
/// \brief What a closest-hit query reports about the surface it found.
#include <rtlab/core/math.hpp>

#include <cstdint>

namespace rtlab {

inline constexpr std::uint32_t kNoPrimitive = 0xFFFFFFFFu;

class Shape;

/// \brief Closest hit: distance, point, normals, surface parameters and which primitive was hit.
struct SurfaceHit {
    float t = kInfinity;
    Point3 point{0.0f};
    /// Per-axis absolute bound on how far `point` may lie from the shape's true surface (rounding of the
    /// hit computation, carried through instances); spawn.hpp offsets secondary rays by it.
    Vec3 point_error{0.0f};
    /// The point in the shape's own object space, for solid textures: `point` for a shape placed directly,
    /// the inner shape's point before the transform through an Instance.
    Point3 object_point{0.0f};
    Normal3 geometric_normal{0.0f, 0.0f, 1.0f};  ///< unit, on the side the shape calls "outside"
    Normal3 shading_normal{0.0f, 0.0f, 1.0f};    ///< unit, interpolated where the shape has vertex normals
    Vec2 uv{0.0f};                               ///< texture coordinates (barycentrics for meshes without uvs)
    Vec3 tangent{1.0f, 0.0f, 0.0f};              ///< unit dP/du direction, orthogonal to shading_normal
    std::uint32_t primitive = kNoPrimitive;      ///< triangle index in a mesh, 0 for single shapes
    bool front_face = true;                      ///< the ray arrived against geometric_normal
    /// The outermost shape hit: an Instance rather than the shape inside it, so two instances of one mesh
    /// can carry two materials (`primitive` still comes from the inner shape).
    const Shape* shape = nullptr;
};

}  // namespace rtlab
