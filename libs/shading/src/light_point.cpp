// Light "point": light from one point, equal in every direction.
//
// Parameters
//   position    point                                                    default [0, 0, 0]
//   intensity   colour, >= 0 (radiant intensity)                         default 1
//
// physical: intensity / r^2 arrives; classic: intensity, at any distance.
#include "light_common.hpp"

namespace rtlab::shading_detail {

namespace {
class PointLight final : public Light {
public:
    PointLight(const Point3& position, const RGB& intensity) : m_position(position), m_intensity(intensity) {}

    bool uses_random_sample() const override { return false; }
    LightSample sample(const Point3& p, int, Vec2, Convention c) const override {
        return point_sample(p, m_position, m_intensity, c);
    }
    RGB power(float) const override { return m_intensity * (4.0f * kPi); }
    bool is_delta() const override { return true; }

private:
    Point3 m_position;
    RGB m_intensity;
};
}  // namespace

LightSample point_sample(const Point3& p, const Point3& position, const RGB& intensity, Convention c) {
    LightSample s;
    s.position = position;
    const Vec3 d = position - p;
    const float r2 = glm::dot(d, d);
    if (!(r2 > 0.0f) || !std::isfinite(r2)) return s;  // at the light itself: nothing defined arrives
    s.wi = d / std::sqrt(r2);
    s.arriving = c == Convention::physical ? intensity / r2 : intensity;
    return s;
}

namespace {
TypeSpec point_spec() {
    TypeSpec s("point light");
    s.add("position", ParamKind::vector, "where it is").defaults("[0, 0, 0]").in("world units");
    s.add("intensity", ParamKind::colour, "divided by r^2 in the physical convention, not in the classic one")
        .defaults("1");
    return s;
}
}  // namespace

void register_point(LightRegistry& registry) {
    registry.add(
        "point",
        [](const Params& p) -> std::shared_ptr<Light> {
            return std::make_shared<PointLight>(finite_vec3(p, "position", Vec3(0.0f)),
                                                non_negative_rgb(p, "intensity", RGB(1.0f)));
        },
        point_spec());
}

}  // namespace rtlab::shading_detail
