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
    Normal3 geometric_normal{0.0f, 0.0f, 1.0f};  ///< unit, on the side the shape calls "outside"
    Normal3 shading_normal{0.0f, 0.0f, 1.0f};    ///< unit, interpolated where the shape has vertex normals
    Vec2 uv{0.0f};                               ///< texture coordinates (barycentrics for meshes without uvs)
    Vec3 tangent{1.0f, 0.0f, 0.0f};              ///< unit dP/du direction, orthogonal to shading_normal
    std::uint32_t primitive = kNoPrimitive;      ///< triangle index in a mesh, 0 for single shapes
    bool front_face = true;                      ///< the ray arrived against geometric_normal
    const Shape* shape = nullptr;                ///< the shape that was hit (set by the shape itself)
};

}  // namespace rtlab
