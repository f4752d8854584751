#pragma once
/// \brief The placement transform scene files and programs share.
#include <rtlab/core/math.hpp>

namespace rtlab {

/// A scene file's {"translate", "rotate", "scale"} transform: scale, then rotate about x, then y, then z
/// (fixed axes, degrees, about the origin), then translate. A program that builds a scene in code calls it to
/// place objects exactly (bit for bit) as the same scene written as a file.
Mat4 scene_transform(const Vec3& translate, const Vec3& rotate_degrees, const Vec3& scale);

}  // namespace rtlab
