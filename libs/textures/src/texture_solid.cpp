// Texture "solid": one colour everywhere.
//
// Parameters
//   color   colour (one number or [r, g, b], linear)   default 1 (white)
#include "texture_params.hpp"

namespace rtlab::detail {

namespace {
class SolidTexture final : public Texture {
public:
    explicit SolidTexture(const RGB& colour) : m_colour(colour) {}
    RGB eval(const TextureLookup&) const override { return m_colour; }
    const RGB* constant() const override { return &m_colour; }

private:
    RGB m_colour;
};
}  // namespace

std::shared_ptr<Texture> make_solid(const RGB& colour) { return std::make_shared<SolidTexture>(colour); }

namespace {
TypeSpec solid_spec() {
    TypeSpec s("one colour everywhere");
    s.add("color", ParamKind::colour, "the colour").defaults("1");
    return s;
}
}  // namespace

void register_solid(TextureRegistry& registry) {
    registry.add(
        "solid",
        [](const Params& p) -> std::shared_ptr<Texture> { return make_solid(finite_rgb(p, "color", RGB(1.0f))); },
        solid_spec());
}

}  // namespace rtlab::detail
