#pragma once
/// \brief Pinhole camera: pixel positions to primary rays.
#include <rtlab/core/math.hpp>
#include <rtlab/core/ray.hpp>

namespace rtlab {

/// \brief Where the camera is, where it looks, and the image it makes.
struct CameraSpec {
    Point3 eye{0.0f, 0.0f, 0.0f};
    Point3 look_at{0.0f, 0.0f, -1.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float vertical_fov_degrees = 45.0f;
    int width = 640;
    int height = 480;
};

/// \brief Pinhole camera. Pixel coordinates run from (0, 0) at the top-left corner of the image to
/// (width, height) at the bottom-right; the centre of pixel (i, j) is (i + 0.5, j + 0.5). With a square
/// image, eye = c + (0, 0, 1.5 diag) and look_at = c, it makes the "primary" ray set of FORMATS.md.
class PinholeCamera {
public:
    /// Throws rtlab::Error for a zero view direction, an up vector parallel to it, a field of view
    /// outside (0, 180) degrees or a non-positive image size.
    explicit PinholeCamera(const CameraSpec& spec);

    /// Unit-direction ray through the image position (x, y), with tmin = 0 and tmax = infinity.
    Ray ray(float x, float y) const;
    const CameraSpec& spec() const { return m_spec; }

private:
    CameraSpec m_spec;
    Vec3 m_forward, m_right, m_up;
    float m_tan_half_fov;
    float m_aspect;
};

}  // namespace rtlab
