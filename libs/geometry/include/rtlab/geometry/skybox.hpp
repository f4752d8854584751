#pragma once
/// \brief The skybox: the six faces of a cube seen from inside, at infinity.
#include <rtlab/core/cube_face.hpp>
#include <rtlab/core/math.hpp>

#include <optional>

namespace rtlab {

/// \brief Which face of the sky a direction sees and where on it, by the one convention of
/// rtlab/core/cube_face.hpp (OpenGL's table, s along columns, t down rows): the cube-map texture uses
/// the same, so the faces of a skybox meet without seams or flips. Only the direction matters (the sky
/// is at infinity); zero, NaN or infinite directions give nullopt.
std::optional<CubeFaceCoord> skybox_lookup(const Vec3& direction);

}  // namespace rtlab
