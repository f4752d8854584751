// An outside project's plugin module: texture "stripes", horizontal bands of two colours in object space.
//   a, b    the two colours                    defaults (0.9, 0.1, 0.1) and (0.1, 0.1, 0.9)
//   width   height of one band, > 0            default 0.25
#include <rtlab/core/param_checks.hpp>
#include <rtlab/scene/plugin_abi.hpp>

#include <cmath>

namespace {

class Stripes final : public rtlab::Texture {
public:
    Stripes(rtlab::RGB a, rtlab::RGB b, float width) : m_a(a), m_b(b), m_width(width) {}
    rtlab::RGB eval(const rtlab::TextureLookup& q) const override {
        const double band = std::floor(static_cast<double>(q.point.y) / m_width);
        return std::fmod(std::abs(band), 2.0) == 0.0 ? m_a : m_b;
    }

private:
    rtlab::RGB m_a, m_b;
    float m_width;
};

std::shared_ptr<rtlab::Texture> make_stripes(const rtlab::Params& p) {
    return std::make_shared<Stripes>(rtlab::finite_rgb(p, "a", rtlab::RGB(0.9f, 0.1f, 0.1f)),
                                     rtlab::finite_rgb(p, "b", rtlab::RGB(0.1f, 0.1f, 0.9f)),
                                     rtlab::positive_float(p, "width", 0.25f));
}

rtlab::TypeSpec stripes_spec() {
    rtlab::TypeSpec s("bands of colours a and b, width high, along object-space y");
    s.add("a", rtlab::ParamKind::colour, "the even bands").defaults("[0.9, 0.1, 0.1]");
    s.add("b", rtlab::ParamKind::colour, "the odd bands").defaults("[0.1, 0.1, 0.9]");
    s.add("width", rtlab::ParamKind::number, "height of one band (> 0)").defaults("0.25").at_least(0);
    return s;
}

void register_types(rtlab::PluginRegistries& r) { r.textures.add("stripes", make_stripes, stripes_spec()); }

}  // namespace

RTLAB_DEFINE_PLUGIN("stripes: two-colour bands", register_types)
