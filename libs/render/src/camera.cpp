#include <rtlab/core/error.hpp>
#include <rtlab/render/camera.hpp>

#include <cmath>
#include <string>

namespace rtlab {

PinholeCamera::PinholeCamera(const CameraSpec& spec) : m_spec(spec) {
    if (spec.width <= 0 || spec.height <= 0)
        throw Error("camera: image size must be positive, got " + std::to_string(spec.width) + "x" +
                    std::to_string(spec.height));
    if (!(spec.vertical_fov_degrees > 0.0f && spec.vertical_fov_degrees < 180.0f))
        throw Error("camera: vertical field of view must lie in (0, 180) degrees, got " +
                    std::to_string(spec.vertical_fov_degrees));
    const Vec3 view = spec.look_at - spec.eye;
    if (!(glm::length(view) > 0.0f) || !is_finite(view))
        throw Error("camera: eye and look_at must differ and be finite");
    m_forward = glm::normalize(view);
    const Vec3 right = glm::cross(m_forward, spec.up);
    if (!(glm::length(right) > 1e-6f * glm::length(spec.up)))
        throw Error("camera: up vector is parallel to the view direction");
    m_right = glm::normalize(right);
    m_up = glm::cross(m_right, m_forward);
    m_tan_half_fov = std::tan(0.5f * spec.vertical_fov_degrees * kPi / 180.0f);
    m_aspect = static_cast<float>(spec.width) / static_cast<float>(spec.height);
}

Ray PinholeCamera::ray(float x, float y) const {
    const float px = (2.0f * x / static_cast<float>(m_spec.width) - 1.0f) * m_tan_half_fov * m_aspect;
    const float py = (1.0f - 2.0f * y / static_cast<float>(m_spec.height)) * m_tan_half_fov;
    return Ray{m_spec.eye, glm::normalize(px * m_right + py * m_up + m_forward)};
}

}  // namespace rtlab
