#pragma once
/// \brief Cameras: image positions (and lens samples) to primary rays.
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

/// \brief What the renderer needs of a camera. Image positions run from (0, 0) at the top-left corner
/// of the image to (width, height) at the bottom-right; the centre of pixel (i, j) is (i + 0.5, j + 0.5).
class Camera {
public:
    virtual ~Camera() = default;
    /// The primary ray through image position `image`; `lens` is a uniform sample in [0, 1)^2 that
    /// cameras with an aperture use to pick the point on the lens (a pinhole ignores it).
    virtual Ray generate_ray(Vec2 image, Vec2 lens) const = 0;
    /// Whether generate_ray() reads the lens sample; false lets the renderer skip hashing it.
    virtual bool uses_lens_sample() const { return true; }
    virtual int width() const = 0;
    virtual int height() const = 0;
};

/// \brief Pinhole camera. With a square image, eye = c + (0, 0, 1.5 diag) and look_at = c, it makes the
/// "primary" ray set of FORMATS.md.
class PinholeCamera : public Camera {
public:
    /// Throws rtlab::Error for a zero view direction, an up vector parallel to it, a field of view
    /// outside (0, 180) degrees or a non-positive image size.
    explicit PinholeCamera(const CameraSpec& spec);

    /// Unit-direction ray through the image position (x, y), with tmin = 0 and tmax = infinity.
    Ray ray(float x, float y) const;
    Ray generate_ray(Vec2 image, Vec2 /*lens*/) const override { return ray(image.x, image.y); }
    bool uses_lens_sample() const override { return false; }
    int width() const override { return m_spec.width; }
    int height() const override { return m_spec.height; }
    const CameraSpec& spec() const { return m_spec; }
    /// The orthonormal camera frame: right, up and forward (towards look_at).
    Vec3 right() const { return m_right; }
    Vec3 up() const { return m_up; }
    Vec3 forward() const { return m_forward; }

private:
    CameraSpec m_spec;
    Vec3 m_forward, m_right, m_up;
    float m_tan_half_fov;
    float m_aspect;
};

}  // namespace rtlab
