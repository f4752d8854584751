#include "orbit_camera.hpp"

#include <cmath>
#include <cstdio>

namespace rtlab::view {

namespace {
// Shortest text that reads back as the same float.
std::string number(float v) {
    char text[32];
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(v));
        if (std::strtof(text, nullptr) == v) break;
    }
    return text;
}
std::string vec(const Vec3& v) { return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]"; }
}  // namespace

OrbitCamera::OrbitCamera(const Camera& scene_camera) {
    if (const auto* pinhole = dynamic_cast<const PinholeCamera*>(&scene_camera)) {
        m_spec = pinhole->spec();
        m_movable = true;
    } else if (const auto* lens = dynamic_cast<const ThinLensCamera*>(&scene_camera)) {
        m_spec = lens->pinhole().spec();
        m_lens.focus_distance = lens->focus_distance();
        m_lens.aperture = lens->aperture();
        m_thin_lens = m_movable = true;
    }
    m_file_spec = m_spec;
}

void OrbitCamera::orbit(float yaw, float pitch) {
    if (!m_movable) return;
    const Vec3 up = glm::normalize(m_spec.up);
    Vec3 offset = m_spec.eye - m_spec.look_at;
    const float distance = glm::length(offset);
    if (!(distance > 0.0f)) return;
    Vec3 dir = offset / distance;
    // Yaw: rotation of the offset about `up` (Rodrigues' formula).
    const float cy = std::cos(yaw), sy = std::sin(yaw);
    dir = dir * cy + glm::cross(up, dir) * sy + up * glm::dot(up, dir) * (1.0f - cy);
    // Pitch: change of the elevation angle, clamped 1 degree short of the poles.
    const float limit = 1.5533430f;  // 89 degrees
    const float elevation = std::asin(std::fmax(-1.0f, std::fmin(1.0f, glm::dot(dir, up))));
    const float target = std::fmax(-limit, std::fmin(limit, elevation + pitch));
    const Vec3 horizontal = dir - up * glm::dot(dir, up);
    const float h = glm::length(horizontal);
    if (h > 1e-6f) dir = horizontal / h * std::cos(target) + up * std::sin(target);
    m_spec.eye = m_spec.look_at + dir * distance;
}

void OrbitCamera::pan(float right, float up) {
    if (!m_movable) return;
    const PinholeCamera frame(m_spec);
    const float distance = glm::length(m_spec.look_at - m_spec.eye);
    const float height = 2.0f * distance * std::tan(glm::radians(m_spec.vertical_fov_degrees) / 2.0f);
    const Vec3 shift = (frame.right() * right + frame.up() * up) * height;
    m_spec.eye += shift;
    m_spec.look_at += shift;
}

void OrbitCamera::dolly(float factor) {
    if (!m_movable) return;
    const Vec3 offset = m_spec.eye - m_spec.look_at;
    const float scale = std::fmax(1e-3f, 1.0f - factor);
    m_spec.eye = m_spec.look_at + offset * scale;
}

bool OrbitCamera::changed() const {
    return m_spec.eye != m_file_spec.eye || m_spec.look_at != m_file_spec.look_at || m_spec.up != m_file_spec.up;
}

std::shared_ptr<const Camera> OrbitCamera::make(const std::shared_ptr<const Camera>& scene_camera) const {
    if (!m_movable || !changed()) return scene_camera;
    if (m_thin_lens) {
        // The focus distance stays the file's: orbiting keeps the plane in focus at the same depth.
        return std::make_shared<ThinLensCamera>(m_spec, m_lens);
    }
    return std::make_shared<PinholeCamera>(m_spec);
}

std::string OrbitCamera::json_snippet() const {
    std::string s = "\"camera\": {";
    if (m_thin_lens) s += "\"type\": \"thin_lens\", ";
    s += "\"position\": " + vec(m_spec.eye) + ", \"look_at\": " + vec(m_spec.look_at) + ", \"up\": " + vec(m_spec.up) +
         ", \"fov\": " + number(m_spec.vertical_fov_degrees);
    if (m_thin_lens)
        s += ", \"aperture\": " + number(m_lens.aperture) + ", \"focus_distance\": " + number(m_lens.focus_distance);
    return s + "}";
}

}  // namespace rtlab::view
