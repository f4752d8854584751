// Light "area": a rectangle that emits on one side (or both), sampled n x n stratified for soft shadows.
//
// Parameters
//   corner      one corner                                               default [0, 0, 0]
//   edge_u      first edge, non-zero                                     default [1, 0, 0]
//   edge_v      second edge, not parallel to edge_u                      default [0, 0, 1]
//   intensity   colour, >= 0: the intensity normal to the rectangle,
//               I = radiance x area (seen from afar, a point light of I)  default 1
//   samples     n, for n x n stratified samples, [1, 64]                 default 4
//   two_sided   emit on both sides                                       default false
//
// Emits towards edge_u x edge_v (edge_u [1,0,0] and edge_v [0,0,1] face down). Each of the n^2 samples is
// a point light of intensity I cos(theta_light) / n^2 at a jittered point of its stratum: physical, divided
// by r^2; classic, not. Nothing arrives behind a one-sided light.
#include "light_common.hpp"

namespace rtlab::shading_detail {

namespace {
class AreaLight final : public Light {
public:
    AreaLight(const Point3& corner, const Vec3& u, const Vec3& v, const RGB& intensity, int n, bool two_sided)
        : m_corner(corner),
          m_u(u),
          m_v(v),
          m_normal(glm::normalize(glm::cross(u, v))),
          m_intensity(intensity / static_cast<float>(n * n)),
          m_n(n),
          m_two_sided(two_sided) {}

    int sample_count() const override { return m_n * m_n; }

    LightSample sample(const Point3& p, int index, Vec2 u, Convention c) const override {
        const float inv = 1.0f / static_cast<float>(m_n);
        const float a = (static_cast<float>(index % m_n) + u.x) * inv;
        const float b = (static_cast<float>(index / m_n) + u.y) * inv;
        LightSample s = point_sample(p, m_corner + a * m_u + b * m_v, m_intensity, c);
        float cos_light = -glm::dot(s.wi, m_normal);
        if (m_two_sided) cos_light = std::abs(cos_light);
        s.arriving *= std::max(0.0f, cos_light);
        return s;
    }

    std::optional<EmittingQuad> emitting_quad() const override {
        const float area = glm::length(glm::cross(m_u, m_v));
        return EmittingQuad{m_corner, m_u, m_v, m_intensity * static_cast<float>(m_n * m_n) / area, m_two_sided};
    }

private:
    Point3 m_corner;
    Vec3 m_u, m_v, m_normal;
    RGB m_intensity;  // per sample
    int m_n;
    bool m_two_sided;
};

TypeSpec area_spec() {
    TypeSpec s(
        "rectangular light corner + a edge_u + b edge_v, n x n stratified samples; emits towards "
        "edge_u x edge_v");
    s.add("corner", ParamKind::vector, "one corner").defaults("[0, 0, 0]").in("world units");
    s.add("edge_u", ParamKind::vector, "the first edge from the corner").defaults("[1, 0, 0]").in("world units");
    s.add("edge_v", ParamKind::vector, "the second edge, not parallel to edge_u")
        .defaults("[0, 0, 1]")
        .in("world units");
    s.add("intensity", ParamKind::colour, "radiance times area").defaults("1");
    s.add("samples", ParamKind::integer, "n: n x n shadow rays per shaded point").defaults("4").range(1, 64);
    s.add("two_sided", ParamKind::boolean, "emits from both sides").defaults("false");
    return s;
}
}  // namespace

void register_area(LightRegistry& registry) {
    registry.add(
        "area",
        [](const Params& p) -> std::shared_ptr<Light> {
            const Vec3 u = finite_vec3(p, "edge_u", Vec3(1.0f, 0.0f, 0.0f));
            const Vec3 v = finite_vec3(p, "edge_v", Vec3(0.0f, 0.0f, 1.0f));
            const Vec3 n = glm::cross(u, v);
            if (!(glm::dot(n, n) > 0.0f) || !is_finite(n))
                fail_param(p, "edge_v", "must be non-zero and not parallel to edge_u");
            return std::make_shared<AreaLight>(finite_vec3(p, "corner", Vec3(0.0f)), u, v,
                                               non_negative_rgb(p, "intensity", RGB(1.0f)),
                                               bounded_int(p, "samples", 4, 1, 64), p.get_bool("two_sided", false));
        },
        area_spec());
}

}  // namespace rtlab::shading_detail
