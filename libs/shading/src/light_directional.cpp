// Light "directional": parallel light from infinitely far away (the Sun as seen from the Earth).
//
// Parameters
//   direction   the direction the light travels, non-zero                 default [0, -1, 0]
//   intensity   colour, >= 0 (irradiance on a surface facing the light)   default 1
//
// The same in both conventions: there is no distance to fall off with.
#include "light_common.hpp"

namespace rtlab::shading_detail {

namespace {
class DirectionalLight final : public Light {
public:
    DirectionalLight(const Vec3& direction, const RGB& intensity) : m_wi(-direction), m_intensity(intensity) {}

    bool uses_random_sample() const override { return false; }
    LightSample sample(const Point3&, int, Vec2, Convention) const override {
        LightSample s;
        s.wi = m_wi;
        s.at_infinity = true;
        s.arriving = m_intensity;
        return s;
    }
    RGB power(float scene_radius) const override { return m_intensity * (kPi * scene_radius * scene_radius); }
    bool is_delta() const override { return true; }

private:
    Vec3 m_wi;
    RGB m_intensity;
};
}  // namespace

RGB non_negative_rgb(const Params& p, std::string_view name, const RGB& fallback) {
    const RGB c = finite_rgb(p, name, fallback);
    if (c.r < 0.0f || c.g < 0.0f || c.b < 0.0f) fail_param(p, name, "must be >= 0");
    return c;
}

Vec3 unit_direction(const Params& p, std::string_view name, const Vec3& fallback) {
    const Vec3 d = finite_vec3(p, name, fallback);
    const float len = glm::length(d);
    if (!(len > 0.0f) || !std::isfinite(len)) fail_param(p, name, "must be a non-zero direction");
    return d / len;
}

namespace {
TypeSpec directional_spec() {
    TypeSpec s("parallel light, as from the sun");
    s.add("direction", ParamKind::vector, "where the light travels (non-zero)").defaults("[0, -1, 0]");
    s.add("intensity", ParamKind::colour, "the irradiance on a surface facing the light").defaults("1");
    return s;
}
}  // namespace

void register_directional(LightRegistry& registry) {
    registry.add(
        "directional",
        [](const Params& p) -> std::shared_ptr<Light> {
            return std::make_shared<DirectionalLight>(unit_direction(p, "direction", Vec3(0.0f, -1.0f, 0.0f)),
                                                      non_negative_rgb(p, "intensity", RGB(1.0f)));
        },
        directional_spec());
}

}  // namespace rtlab::shading_detail
