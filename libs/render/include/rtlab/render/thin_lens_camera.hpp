#pragma once
/// \brief Thin-lens camera: depth of field from a circular aperture focused on a plane.
#include <rtlab/render/camera.hpp>

namespace rtlab {

/// \brief The lens: its diameter and the distance, along the view direction, of the plane in focus.
struct LensSpec {
    float aperture = 0.0f;        ///< lens diameter in scene units; 0 is a pinhole
    float focus_distance = 0.0f;  ///< 0 focuses on look_at (its distance along the view direction)
};

/// \brief Thin-lens camera. Every ray through image position p passes through the point where the
/// pinhole ray through p meets the focus plane, so that plane is sharp; the ray starts at a point of
/// the lens disc (radius aperture / 2, in the plane through the eye spanned by the camera's right and
/// up), chosen from the lens sample by Shirley's concentric map. With aperture 0 it returns exactly the
/// pinhole camera's rays.
class ThinLensCamera : public Camera {
public:
    /// Throws rtlab::Error for what PinholeCamera rejects, and for a negative or non-finite aperture or
    /// focus distance.
    ThinLensCamera(const CameraSpec& spec, const LensSpec& lens);

    Ray generate_ray(Vec2 image, Vec2 lens) const override;
    int width() const override { return m_pinhole.width(); }
    int height() const override { return m_pinhole.height(); }
    const PinholeCamera& pinhole() const { return m_pinhole; }
    /// The focus distance in use (look_at's depth when the spec said 0).
    float focus_distance() const { return m_focus_distance; }
    /// The lens diameter (LensSpec::aperture).
    float aperture() const { return 2.0f * m_lens_radius; }

private:
    PinholeCamera m_pinhole;
    float m_lens_radius;
    float m_focus_distance;
};

/// Shirley and Chiu's concentric map of [0, 1)^2 onto the unit disc (area-preserving, low distortion).
Vec2 concentric_disc(Vec2 u);

}  // namespace rtlab
