// Light "spot": a point light limited to a cone, with a soft edge.
//
// Parameters
//   position     point                                                   default [0, 0, 0]
//   direction    the cone's axis, non-zero                               default [0, -1, 0]
//   intensity    colour, >= 0, on the axis                               default 1
//   cone_angle   half-angle of the cone in degrees, (0, 90]              default 30
//   falloff      width in degrees of the soft edge inside the cone,
//                [0, cone_angle]: full intensity up to cone_angle -
//                falloff, smoothstep down to 0 at cone_angle             default 5
//
// Falls off with distance as a point light does (physical: 1 / r^2; classic: not at all).
#include "light_common.hpp"

namespace rtlab::shading_detail {

namespace {
class SpotLight final : public Light {
public:
    SpotLight(const Point3& position, const Vec3& axis, const RGB& intensity, float cone, float falloff)
        : m_position(position),
          m_axis(axis),
          m_intensity(intensity),
          m_cos_outer(std::cos(cone)),
          m_cos_inner(std::cos(cone - falloff)) {}

    bool uses_random_sample() const override { return false; }
    LightSample sample(const Point3& p, int, Vec2, Convention c) const override {
        LightSample s = point_sample(p, m_position, m_intensity, c);
        const float cos_theta = -glm::dot(s.wi, m_axis);
        s.arriving *= cone_factor(cos_theta);
        return s;
    }
    // The smoothstep's mean over cos between the cones is 1/2: full cone inside, half the band.
    RGB power(float) const override { return m_intensity * (2.0f * kPi * (1.0f - 0.5f * (m_cos_inner + m_cos_outer))); }
    bool is_delta() const override { return true; }
    std::optional<EmissionCone> emission_cone() const override { return EmissionCone{m_axis, m_cos_outer}; }

private:
    float cone_factor(float cos_theta) const {
        if (!(cos_theta > m_cos_outer)) return 0.0f;
        if (cos_theta >= m_cos_inner) return 1.0f;
        const float x = (cos_theta - m_cos_outer) / (m_cos_inner - m_cos_outer);
        return x * x * (3.0f - 2.0f * x);
    }

    Point3 m_position;
    Vec3 m_axis;
    RGB m_intensity;
    float m_cos_outer, m_cos_inner;
};

TypeSpec spot_spec() {
    TypeSpec s("spot light: a point light limited to a cone, with a soft edge");
    s.add("position", ParamKind::vector, "the cone's apex").defaults("[0, 0, 0]").in("world units");
    s.add("direction", ParamKind::vector, "the cone's axis (non-zero)").defaults("[0, -1, 0]");
    s.add("intensity", ParamKind::colour, "falls off as a point light's").defaults("1");
    s.add("cone_angle", ParamKind::number, "half-angle of the cone").defaults("30").range(1e-3, 90).in("degrees");
    s.add("falloff", ParamKind::number, "soft edge inside the cone, at most cone_angle (default: 5 or cone_angle)")
        .range(0, 90)
        .in("degrees");
    return s;
}
}  // namespace

void register_spot(LightRegistry& registry) {
    registry.add(
        "spot",
        [](const Params& p) -> std::shared_ptr<Light> {
            const float cone = float_in_range(p, "cone_angle", 30.0f, 1e-3f, 90.0f);
            const float falloff = float_in_range(p, "falloff", std::min(5.0f, cone), 0.0f, cone);
            const float rad = kPi / 180.0f;
            return std::make_shared<SpotLight>(finite_vec3(p, "position", Vec3(0.0f)),
                                               unit_direction(p, "direction", Vec3(0.0f, -1.0f, 0.0f)),
                                               non_negative_rgb(p, "intensity", RGB(1.0f)), cone * rad, falloff * rad);
        },
        spot_spec());
}

}  // namespace rtlab::shading_detail
