#pragma once
/// \brief Where a shape's uv lies in world space: what the level of detail of a filtered texture on it is worked
/// out from (rtlab/render/texture_level.hpp). Each shape says its own (Shape::uv_footprint), so a scene loader
/// needs to know nothing of spheres or disks.
#include <rtlab/core/math.hpp>

namespace rtlab {

/// \brief A bounding sphere (centre, radius) in world space, and the world length one whole period of u covers
/// on the surface (the texels of the map's width lie along it).
struct UvFootprint {
    Point3 centre{0.0f};
    float radius = 0.0f;
    float u_length = 0.0f;
};

/// A sphere (rtlab::Sphere: u is the longitude) placed by `to_world`: u runs round its equator.
/// The radius is scaled by the largest axis scale of `to_world`.
UvFootprint sphere_footprint(const Mat4& to_world, const Point3& centre, float radius);

/// A disk or annulus (rtlab::Disk: u runs from the inner to the outer edge) placed by `to_world`.
UvFootprint disk_footprint(const Mat4& to_world, const Point3& centre, float radius, float inner_radius);

}  // namespace rtlab
