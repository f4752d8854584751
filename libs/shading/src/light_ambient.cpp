// Light "ambient": light arriving equally from every direction, never shadowed.
//
// Parameters
//   intensity   colour, >= 0                                             default 0.1
//
// A material reflects its diffuse colour times the intensity (both conventions: a Lambert surface under
// uniform radiance L reflects albedo L). Shadow rays are not traced for it.
#include "light_common.hpp"

namespace rtlab::shading_detail {

namespace {
class AmbientLight final : public Light {
public:
    explicit AmbientLight(const RGB& intensity) : m_intensity(intensity) {}
    int sample_count() const override { return 0; }
    bool uses_random_sample() const override { return false; }
    LightSample sample(const Point3&, int, Vec2, Convention) const override { return {}; }
    RGB ambient() const override { return m_intensity; }

private:
    RGB m_intensity;
};

TypeSpec ambient_spec() {
    TypeSpec s("ambient light, never shadowed; adds diffuse colour x intensity (classic convention)");
    s.add("intensity", ParamKind::colour, "the ambient light").defaults("0.1");
    return s;
}
}  // namespace

void register_ambient(LightRegistry& registry) {
    registry.add(
        "ambient",
        [](const Params& p) -> std::shared_ptr<Light> {
            return std::make_shared<AmbientLight>(non_negative_rgb(p, "intensity", RGB(0.1f)));
        },
        ambient_spec());
}

}  // namespace rtlab::shading_detail
