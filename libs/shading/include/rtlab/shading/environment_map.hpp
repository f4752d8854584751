#pragma once
/// \brief An environment light from an image: an equirectangular (latitude-longitude) map or a cube map, turned
/// about the up axis and scaled, looked up bilinearly and importance-sampled by luminance.
///
/// Orientation (world space is right-handed with +y up). Equirectangular: row 0 of the image is straight up
/// (+y), the last row straight down; u = (x + 0.5) / width runs round the horizon with u = 0 (the image's left
/// edge) facing -x, u = 0.25 facing -z, u = 0.5 (the centre column) facing +x and u = 0.75 facing +z. Seen from
/// inside, as the camera sees the sky, the map is not mirrored: turning right from the centre column (from +x
/// towards +z) walks right across the image. This is Blender's orientation for its world textures once its
/// z-up world is turned y-up (Blender's -y becomes +z). Cube maps: the faces of rtlab/core/cube_face.hpp, also
/// unmirrored from inside. rotation_degrees turns the map about +y by the right-hand rule (counter-clockwise seen
/// from above): at 90 degrees the centre column faces -z.
///
/// Sampling: a piecewise-constant 2D distribution (rtlab/core/distribution.hpp) on half-texel cells, each weighted
/// by the largest luminance among the 2 x 2 texels the bilinear lookup blends there, so its density is positive
/// wherever the looked-up radiance is; times sin(theta) for an equirectangular map (the solid angle of its rows)
/// and times each cube face's Jacobian 4 / (1 + s'^2 + t'^2)^(3/2) (s', t' in [-1, 1] across the face). Densities
/// are per solid angle: the distribution's over [0, 1)^2 divided by 2 pi^2 sin(theta), or multiplied by
/// (1 + s'^2 + t'^2)^(3/2) / 24 for the six faces stacked in one table. A cell holding less than 2^-24 of its row
/// (or a row of the whole) can be missed by a float random number: such light is found by BSDF sampling alone.
#include <rtlab/core/distribution.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/shading/emitter.hpp>
#include <rtlab/textures/cube_map.hpp>

#include <array>
#include <memory>

namespace rtlab {

/// \brief How an environment map is placed and scaled.
struct EnvironmentMapOptions {
    float rotation_degrees = 0.0f;  ///< about +y, right-handed (counter-clockwise seen from above)
    RGB intensity{1.0f};            ///< multiplies every texel
    float scene_radius = 1.0f;      ///< for power(): see EnvironmentEmitter::for_scene_radius
};

/// \brief An equirectangular or cube environment map as a light. Copies for other scene radii share the image
/// and its distribution. Thread-safe: all methods are const.
class EnvironmentMap final : public EnvironmentEmitter {
public:
    /// An equirectangular map of any size (2:1 is usual). Negative texels read as 0. Throws rtlab::Error for an
    /// empty image, a texel that is not finite, or an intensity that is negative or not finite.
    EnvironmentMap(Image equirectangular, const EnvironmentMapOptions& options = {});
    /// A cube map, faces in the order px nx py ny pz nz, square and of one size; looked up as CubeMapTexture
    /// does (seamless across the edges). Throws rtlab::Error as above and for faces of the wrong shape.
    EnvironmentMap(std::array<Image, 6> faces, const EnvironmentMapOptions& options = {});

    RGB radiance(const Vec3& direction) const override;
    std::optional<EmitterSample> sample_li(const Point3& p, const Vec2& u) const override;
    float pdf_li(const Point3& p, const Vec3& wi, const Point3& on_light, const Normal3& normal) const override;
    /// radiance_integral() x pi r^2.
    RGB power() const override;
    std::shared_ptr<const EnvironmentEmitter> for_scene_radius(float scene_radius) const override;

    /// The radiance integrated over the sphere of directions (texel by texel, intensity included).
    RGB radiance_integral() const;
    bool is_cube() const;
    /// The sampling distribution over [0, 1)^2 (equirectangular: 2 width x 2 height cells, u across, v down from
    /// +y; cube: 2 n x 12 n cells, the faces stacked in the order px nx py ny pz nz).
    const Distribution2D& distribution() const;
    const EnvironmentMapOptions& options() const { return m_options; }

private:
    struct Data;
    static std::shared_ptr<const Data> build(Image equirectangular);
    static std::shared_ptr<const Data> build(std::array<Image, 6> faces);
    EnvironmentMap(std::shared_ptr<const Data> data, const EnvironmentMapOptions& options);
    Vec3 to_local(const Vec3& w) const;
    Vec3 to_world(const Vec3& l) const;
    RGB lookup(const Vec3& local) const;  // unit local direction, without the intensity
    float pdf_local(const Vec3& local) const;

    std::shared_ptr<const Data> m_data;
    EnvironmentMapOptions m_options;
    float m_cos = 1.0f, m_sin = 0.0f;  // of the rotation
};

}  // namespace rtlab
