#pragma once
/// \brief A cube map (skybox) looked up by direction, with seamless bilinear filtering across faces.
///
/// Face convention: see rtlab/core/cube_face.hpp (OpenGL's cube-map table). A horizontal cross image is
/// 4N x 3N with py above pz, the middle row nx pz px nz, and ny below pz: the six faces, unrotated.
#include <rtlab/core/cube_face.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/textures/texture.hpp>

#include <array>
#include <filesystem>
#include <memory>

namespace rtlab {

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
    /// Texel (x, y) of a face as sample() reads it: x and y may be one texel beyond the face (-1 or
    /// face_size()), which reads the neighbouring face (at a cube corner, the mean of the three).
    RGB texel(CubeFace face, int x, int y) const;

private:
    std::array<Image, 6> m_faces;
    int m_size = 0;
};

}  // namespace rtlab
