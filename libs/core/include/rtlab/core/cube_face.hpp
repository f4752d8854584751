#pragma once
/// \brief Which face of a cube, and where on it, a direction points to: the one cube-map convention
/// shared by the skybox (geometry) and the cube-map texture (textures).
///
/// Face convention: OpenGL's "selection of cube map images" table, which Direct3D shares. Faces are
/// indexed px=0, nx=1, py=2, ny=3, pz=4, nz=5. For a direction (x, y, z) the face is the axis of the
/// largest |component| (ties go to x, then y), with ma that component, and
///
///   face  sc   tc        face  sc   tc
///   px    -z   -y        nx    +z   -y
///   py    +x   +z        ny    +x   -z
///   pz    +x   -y        nz    -x   -y
///
/// s = (sc/|ma| + 1)/2 runs along the columns left to right, t = (tc/|ma| + 1)/2 along the rows top to
/// bottom (row 0 is the first row of the file). In a right-handed, y-up world, the map then shows the sky
/// unmirrored to a viewer at the origin.
#include <rtlab/core/math.hpp>

namespace rtlab {

enum class CubeFace { px = 0, nx = 1, py = 2, ny = 3, pz = 4, nz = 5 };

/// \brief Where a direction lands: the face and (s, t) in [0, 1]^2 on it.
struct CubeFaceCoord {
    CubeFace face = CubeFace::px;
    float s = 0.5f;
    float t = 0.5f;
};

/// The face and face coordinates of a direction (need not be unit length; must be non-zero and finite).
CubeFaceCoord cube_face_coord(const Vec3& direction);
/// A direction (not normalised) that lands on face at (s, t); s, t may lie outside [0, 1], which
/// gives directions beyond the face's edges (used to find a neighbouring face's texels).
Vec3 cube_face_direction(CubeFace face, float s, float t);

}  // namespace rtlab
