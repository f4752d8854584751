#pragma once
// The viewer's camera controls: orbit about the look-at point, pan, dolly, and the camera as a JSON snippet.
#include <rtlab/render/camera.hpp>
#include <rtlab/render/thin_lens_camera.hpp>

#include <memory>
#include <string>

namespace rtlab::view {

/// \brief The camera the viewer renders with: the file's (kept for reset) and the one the mouse moved.
class OrbitCamera {
public:
    OrbitCamera() = default;
    /// Takes the scene's camera; a pinhole or thin-lens camera can be moved, another kind only shown.
    explicit OrbitCamera(const Camera& scene_camera);

    bool movable() const { return m_movable; }
    /// Rotates the eye about look_at: `yaw` about the up axis, `pitch` towards it (radians); the pitch stops
    /// short of the poles so the view never flips.
    void orbit(float yaw, float pitch);
    /// Moves eye and look_at along the image plane by fractions of the view's height at the look-at distance.
    void pan(float right, float up);
    /// Moves the eye towards look_at by `factor` of the distance (0.1: 10% closer; negative: away).
    void dolly(float factor);
    void reset() { m_spec = m_file_spec; }
    bool changed() const;

    const CameraSpec& spec() const { return m_spec; }
    /// A camera for the renderer: the scene's own object while unchanged, else a new one of its kind.
    std::shared_ptr<const Camera> make(const std::shared_ptr<const Camera>& scene_camera) const;
    /// {"camera": {"position": [...], "look_at": [...], "up": [...], "fov": ...}} to paste into a scene file
    /// (with "type", "aperture" and "focus_distance" for a thin lens).
    std::string json_snippet() const;

private:
    CameraSpec m_file_spec, m_spec;
    LensSpec m_lens;
    bool m_thin_lens = false;
    bool m_movable = false;
};

}  // namespace rtlab::view
