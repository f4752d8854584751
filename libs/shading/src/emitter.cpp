#include <rtlab/core/error.hpp>
#include <rtlab/core/frame.hpp>
#include <rtlab/shading/emitter.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

namespace {

// A point's solid-angle density from an area density: dA = r^2 dw / |cos|.
float area_to_solid_angle(float pdf_area, const Point3& p, const Point3& y, const Normal3& n) {
    const Vec3 d = y - p;
    const float dist2 = glm::dot(d, d);
    const float cos_l = std::abs(glm::dot(d, n)) / std::sqrt(dist2);
    if (!(cos_l > 0.0f) || !(dist2 > 0.0f)) return 0.0f;
    return pdf_area * dist2 / cos_l;
}

}  // namespace

Vec3 sample_uniform_sphere(const Vec2& u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

AreaEmitter::AreaEmitter(EmitterShape shape, const RGB& radiance, bool two_sided)
    : m_shape(std::move(shape)), m_radiance(radiance), m_two_sided(two_sided) {
    switch (m_shape.kind) {
        case EmitterShape::Kind::triangles: {
            // Sums in double so that a mesh of a million triangles keeps its small ones' share.
            double sum = 0.0;
            m_cdf.reserve(m_shape.triangles.size());
            m_normals.reserve(m_shape.triangles.size());
            for (const auto& t : m_shape.triangles) {
                const Vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
                sum += 0.5 * static_cast<double>(glm::length(n));
                m_cdf.push_back(static_cast<float>(sum));
                m_normals.push_back(glm::normalize(n));
            }
            m_area = static_cast<float>(sum);
            break;
        }
        case EmitterShape::Kind::disk:
            m_area = kPi * (m_shape.radius * m_shape.radius - m_shape.inner_radius * m_shape.inner_radius);
            break;
        case EmitterShape::Kind::sphere:
            m_area = 4.0f * kPi * m_shape.radius * m_shape.radius;
            break;
    }
    if (!(m_area > 0.0f) || !std::isfinite(m_area)) throw Error("area light: the emitting shape has no area");
}

RGB AreaEmitter::power() const { return m_radiance * (m_area * kPi * (m_two_sided ? 2.0f : 1.0f)); }

AreaEmitter::SurfacePoint AreaEmitter::sample_area(const Vec2& u) const {
    switch (m_shape.kind) {
        case EmitterShape::Kind::triangles: {
            // Choose a triangle by area, then reuse u.x rescaled within its share.
            const float target = u.x * m_area;
            const auto it = std::upper_bound(m_cdf.begin(), m_cdf.end(), target);
            const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(it - m_cdf.begin()), m_cdf.size() - 1);
            const float lo = i == 0 ? 0.0f : m_cdf[i - 1];
            const float share = m_cdf[i] - lo;
            const float ux = share > 0.0f ? std::clamp((target - lo) / share, 0.0f, 0.99999994f) : 0.5f;
            const auto& t = m_shape.triangles[i];
            const float su = std::sqrt(ux);
            const float b0 = 1.0f - su, b1 = u.y * su;
            return {b0 * t[0] + b1 * t[1] + (1.0f - b0 - b1) * t[2], m_normals[i]};
        }
        case EmitterShape::Kind::disk: {
            const float r2i = m_shape.inner_radius * m_shape.inner_radius;
            const float r = std::sqrt(r2i + u.x * (m_shape.radius * m_shape.radius - r2i));
            const float phi = 2.0f * kPi * u.y;
            const Frame f = Frame::from_normal(m_shape.normal);
            return {m_shape.centre + f.to_world(Vec3(r * std::cos(phi), r * std::sin(phi), 0.0f)), m_shape.normal};
        }
        case EmitterShape::Kind::sphere: {
            const Vec3 d = sample_uniform_sphere(u);
            return {m_shape.centre + m_shape.radius * d, m_shape.inward ? -d : d};
        }
    }
    return {};
}

// Whether p sees the sphere as a cone (p outside), with cos of its half-angle; 1 - cos kept accurate for small cones.
bool AreaEmitter::sphere_cone(const Point3& p, float& cos_max, float& one_minus_cos_max) const {
    const Vec3 pc = m_shape.centre - p;
    const float d2 = glm::dot(pc, pc);
    const float r2 = m_shape.radius * m_shape.radius;
    // Points on or just off the surface sample by area: the cone degenerates into the hemisphere there.
    if (!(d2 > r2 * 1.0001f)) return false;
    const float sin2 = r2 / d2;
    cos_max = std::sqrt(std::max(0.0f, 1.0f - sin2));
    one_minus_cos_max = sin2 / (1.0f + cos_max);
    return true;
}

std::optional<EmitterSample> AreaEmitter::sample_li(const Point3& p, const Vec2& u) const {
    EmitterSample s;
    Normal3 n;
    float cos_max = 0.0f, one_minus = 0.0f;
    if (m_shape.kind == EmitterShape::Kind::sphere && sphere_cone(p, cos_max, one_minus)) {
        // Uniform in the cone: cos theta = 1 - u.x (1 - cos_max); the point is where that direction meets the
        // sphere first.
        const Vec3 pc = m_shape.centre - p;
        const float dc = glm::length(pc);
        const float one_minus_cos = u.x * one_minus;
        const float cos_t = 1.0f - one_minus_cos;
        const float sin2_t = one_minus_cos * (2.0f - one_minus_cos);
        const float sin_t = std::sqrt(std::max(0.0f, sin2_t));
        const float phi = 2.0f * kPi * u.y;
        const Frame f = Frame::from_normal(pc / dc);
        s.wi = glm::normalize(f.to_world(Vec3(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t)));
        const float r2 = m_shape.radius * m_shape.radius;
        const float dist = dc * cos_t - std::sqrt(std::max(0.0f, r2 - dc * dc * sin2_t));
        s.position = p + dist * s.wi;
        n = glm::normalize(s.position - m_shape.centre);
        if (m_shape.inward) n = -n;
        s.pdf = 1.0f / (2.0f * kPi * one_minus);
    } else {
        const SurfacePoint y = sample_area(u);
        const Vec3 d = y.point - p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return std::nullopt;
        s.wi = d / std::sqrt(dist2);
        s.position = y.point;
        n = y.normal;
        s.pdf = area_to_solid_angle(1.0f / m_area, p, y.point, y.normal);
    }
    const float cos_l = -glm::dot(s.wi, n);
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf) || (!m_two_sided && !(cos_l > 0.0f))) return std::nullopt;
    s.radiance = m_radiance;
    return s;
}

float AreaEmitter::pdf_li(const Point3& p, const Vec3&, const Point3& on_light, const Normal3& normal) const {
    float cos_max = 0.0f, one_minus = 0.0f;
    if (m_shape.kind == EmitterShape::Kind::sphere && sphere_cone(p, cos_max, one_minus))
        return 1.0f / (2.0f * kPi * one_minus);
    return area_to_solid_angle(1.0f / m_area, p, on_light, normal);
}

std::optional<EmitterSample> UniformEnvironment::sample_li(const Point3& p, const Vec2& u) const {
    EmitterSample s;
    s.wi = sample_uniform_sphere(u);
    s.position = p + s.wi;
    s.at_infinity = true;
    s.radiance = m_radiance;
    s.pdf = 1.0f / (4.0f * kPi);
    return s;
}

float UniformEnvironment::pdf_li(const Point3&, const Vec3&, const Point3&, const Normal3&) const {
    return 1.0f / (4.0f * kPi);
}

RGB UniformEnvironment::power() const { return m_radiance * (4.0f * kPi * kPi * m_radius * m_radius); }

DeltaEmitter::DeltaEmitter(std::shared_ptr<const Light> light, float scene_radius) : m_light(std::move(light)) {
    if (!m_light || !m_light->is_delta()) throw Error("delta light: not a point, spot or directional light");
    m_power = m_light->power(scene_radius);
}

std::optional<EmitterSample> DeltaEmitter::sample_li(const Point3& p, const Vec2& u) const {
    const LightSample ls = m_light->sample(p, 0, u, Convention::physical);
    if (ls.arriving.is_black()) return std::nullopt;
    EmitterSample s;
    s.wi = ls.wi;
    s.position = ls.position;
    s.at_infinity = ls.at_infinity;
    s.radiance = ls.arriving;
    s.pdf = 1.0f;
    return s;
}

}  // namespace rtlab
