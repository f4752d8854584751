#include <rtlab/core/error.hpp>
#include <rtlab/render/thin_lens_camera.hpp>

#include <cmath>
#include <string>

namespace rtlab {

Vec2 concentric_disc(Vec2 u) {
    const float a = 2.0f * u.x - 1.0f;
    const float b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return Vec2(0.0f);
    if (std::abs(a) > std::abs(b)) {
        const float phi = 0.25f * kPi * (b / a);
        return a * Vec2(std::cos(phi), std::sin(phi));
    }
    const float phi = 0.5f * kPi - 0.25f * kPi * (a / b);
    return b * Vec2(std::cos(phi), std::sin(phi));
}

ThinLensCamera::ThinLensCamera(const CameraSpec& spec, const LensSpec& lens) : m_pinhole(spec) {
    if (!(lens.aperture >= 0.0f) || !std::isfinite(lens.aperture))
        throw Error("camera: aperture must be a finite number >= 0, got " + std::to_string(lens.aperture));
    if (!(lens.focus_distance >= 0.0f) || !std::isfinite(lens.focus_distance))
        throw Error("camera: focus distance must be a finite number >= 0, got " + std::to_string(lens.focus_distance));
    m_lens_radius = 0.5f * lens.aperture;
    m_focus_distance =
        lens.focus_distance > 0.0f ? lens.focus_distance : glm::dot(spec.look_at - spec.eye, m_pinhole.forward());
}

Ray ThinLensCamera::generate_ray(Vec2 image, Vec2 lens) const {
    Ray r = m_pinhole.ray(image.x, image.y);
    // The pinhole ray is returned untouched, not recomputed through the focus point, so that aperture 0
    // gives bit-identical images.
    if (m_lens_radius == 0.0f) return r;
    const Point3 focus = r.origin + r.direction * (m_focus_distance / glm::dot(r.direction, m_pinhole.forward()));
    const Vec2 d = m_lens_radius * concentric_disc(lens);
    r.origin += d.x * m_pinhole.right() + d.y * m_pinhole.up();
    r.direction = glm::normalize(focus - r.origin);
    return r;
}

}  // namespace rtlab
