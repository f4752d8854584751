#pragma once
/// \brief A cube map (skybox) looked up by direction, with seamless bilinear filtering across faces.
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
/// unmirrored to a viewer at the origin. A horizontal cross image is 4N x 3N with py above pz, the middle
/// row nx pz px nz, and ny below pz: exactly the six faces above, unrotated.
#include <rtlab/core/image.hpp>
#include <rtlab/textures/texture.hpp>

#include <array>
#include <filesystem>
#include <memory>

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

/// \brief Six square faces of equal size. Bilinear filtering fetches the texels beyond a face's edge
/// from the neighbouring face, so the map is continuous across all 12 edges; at a cube corner the
/// missing fourth texel is the mean of the three faces' corner texels.
class CubeMapTexture final : public Texture {
public:
    /// Faces in the order px nx py ny pz nz; all square and the same size, else rtlab::Error.
    explicit CubeMapTexture(std::array<Image, 6> faces);
    /// Cuts the six faces out of a horizontal cross (4N x 3N).
    static std::shared_ptr<CubeMapTexture> from_cross(const Image& cross);
    /// Loads six files (px nx py ny pz nz) or one cross file; errors name the file at fault.
    static std::shared_ptr<CubeMapTexture> load_faces(const std::array<std::filesystem::path, 6>& paths,
                                                      ColorEncoding encoding = ColorEncoding::srgb);
    static std::shared_ptr<CubeMapTexture> load_cross(const std::filesystem::path& path,
                                                      ColorEncoding encoding = ColorEncoding::srgb);

    /// Reads lookup.direction; a zero or non-finite direction gives black.
    RGB eval(const TextureLookup& lookup) const override { return sample(lookup.direction); }
    RGB sample(const Vec3& direction) const;
    int face_size() const { return m_size; }
    const Image& face(CubeFace f) const { return m_faces[static_cast<int>(f)]; }

private:
    RGB texel(CubeFace face, int x, int y) const;  // x, y may be one texel beyond the face

    std::array<Image, 6> m_faces;
    int m_size = 0;
};

}  // namespace rtlab
