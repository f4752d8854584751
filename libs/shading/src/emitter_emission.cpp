// Emitter::sample_le: photons leaving each kind of light (photon mapping). Each photon's power is worked out from
// the light's total rather than as radiance cos / (pdf pdf), so that the mean over photons equals the emitted
// power to the last bit wherever the sampling is exact (area lights, the environment).
#include <rtlab/core/frame.hpp>
#include <rtlab/shading/bsdf.hpp>
#include <rtlab/shading/emitter.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

namespace {

// A photon from infinitely far away along -toward: from a disk of the scene's radius perpendicular to the direction,
// centred on the scene's centre pushed back by the radius towards the light, so every photon starts outside the
// scene and the disk covers it.
EmissionSample from_infinity(const Vec3& toward, const Vec2& u, const SceneSphere& scene) {
    EmissionSample s;
    s.direction = -toward;
    const float r = scene.radius * std::sqrt(u.x);
    const float phi = 2.0f * kPi * u.y;
    const Frame f = Frame::from_normal(s.direction);
    s.position = scene.centre + scene.radius * toward + f.to_world(Vec3(r * std::cos(phi), r * std::sin(phi), 0.0f));
    s.pdf_position = 1.0f / (kPi * scene.radius * scene.radius);
    return s;
}

}  // namespace

Vec3 sample_uniform_cone(const Vec2& u, float cos_max) {
    // 1 - cos theta directly, so that narrow cones keep their angles.
    const float one_minus_cos = u.x * (1.0f - cos_max);
    const float cos_t = 1.0f - one_minus_cos;
    const float sin_t = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
    const float phi = 2.0f * kPi * u.y;
    return {sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t};
}

std::optional<EmissionSample> Emitter::sample_le(const Vec2&, const Vec2&, const SceneSphere&) const {
    return std::nullopt;
}

std::optional<EmissionSample> AreaEmitter::sample_le(const Vec2& u_position, const Vec2& u_direction,
                                                     const SceneSphere&) const {
    const SurfacePoint y = sample_area(u_position);
    Vec2 u = u_direction;
    Normal3 n = y.normal;
    float sides = 1.0f;
    if (m_two_sided) {
        // u.x picks the face and is stretched back over [0, 1) for the direction.
        sides = 2.0f;
        if (u.x < 0.5f) {
            u.x = 2.0f * u.x;
        } else {
            u.x = std::min(2.0f * u.x - 1.0f, 0x1.fffffep-1f);
            n = -n;
        }
    }
    const Vec3 local = sample_cosine_hemisphere(u);
    if (!(local.z > 0.0f)) return std::nullopt;
    EmissionSample s;
    s.position = y.point;
    s.normal = n;
    s.direction = glm::normalize(Frame::from_normal(n).to_world(local));
    s.radiance = m_radiance;
    s.pdf_position = 1.0f / m_area;
    s.pdf_direction = local.z / (kPi * sides);
    // radiance cos / (pdf_position pdf_direction), the cosines cancelled.
    s.power = m_radiance * (m_area * kPi * sides);
    return s;
}

std::optional<EmissionSample> EnvironmentEmitter::sample_le(const Vec2& u_position, const Vec2& u_direction,
                                                            const SceneSphere& scene) const {
    // sample_li's answer does not depend on the point for a light at infinity: its direction towards the light
    // and density are those of the photon's (reversed) direction.
    const std::optional<EmitterSample> li = sample_li(scene.centre, u_direction);
    if (!li || !(li->pdf > 0.0f) || li->radiance.is_black()) return std::nullopt;
    EmissionSample s = from_infinity(li->wi, u_position, scene);
    s.radiance = li->radiance;
    s.pdf_direction = li->pdf;
    s.power = li->radiance * (1.0f / (li->pdf * s.pdf_position));
    return s;
}

std::optional<EmissionSample> UniformEnvironment::sample_le(const Vec2& u_position, const Vec2& u_direction,
                                                            const SceneSphere& scene) const {
    EmissionSample s = from_infinity(sample_uniform_sphere(u_direction), u_position, scene);
    s.radiance = m_radiance;
    s.pdf_direction = 1.0f / (4.0f * kPi);
    s.power = m_radiance * (4.0f * kPi * kPi * scene.radius * scene.radius);
    return s;
}

std::optional<EmissionSample> DeltaEmitter::sample_le(const Vec2& u_position, const Vec2& u_direction,
                                                      const SceneSphere& scene) const {
    // The Light interface answers "what arrives at a point": its position, direction and intensity are read from
    // that (a point-like light's intensity towards d is what arrives at the light's position + d times r^2).
    const LightSample probe = m_light->sample(scene.centre, 0, Vec2(0.5f), Convention::physical);
    if (probe.at_infinity) {
        if (probe.arriving.is_black()) return std::nullopt;
        EmissionSample s = from_infinity(probe.wi, u_position, scene);
        s.radiance = probe.arriving;
        s.pdf_direction = 1.0f;
        s.delta_direction = true;
        s.power = probe.arriving * (kPi * scene.radius * scene.radius);
        return s;
    }
    EmissionSample s;
    s.position = probe.position;
    s.pdf_position = 1.0f;
    s.delta_position = true;
    if (const std::optional<EmissionCone> cone = m_light->emission_cone()) {
        const Vec3 local = sample_uniform_cone(u_direction, cone->cos_max);
        s.direction = glm::normalize(Frame::from_normal(cone->axis).to_world(local));
        s.pdf_direction = 1.0f / (2.0f * kPi * (1.0f - cone->cos_max));
    } else {
        s.direction = sample_uniform_sphere(u_direction);
        s.pdf_direction = 1.0f / (4.0f * kPi);
    }
    const Point3 q = s.position + s.direction;
    const Vec3 back = s.position - q;
    const LightSample towards = m_light->sample(q, 0, Vec2(0.5f), Convention::physical);
    s.radiance = towards.arriving * glm::dot(back, back);
    if (s.radiance.is_black()) return std::nullopt;
    s.power = s.radiance * (1.0f / s.pdf_direction);
    return s;
}

}  // namespace rtlab
