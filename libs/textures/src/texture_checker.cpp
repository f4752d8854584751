// Texture "checker": a 2D checkerboard in uv.
//
// Tile (i, j) = (floor(u * tiles_u), floor(v * tiles_v)); tiles with i + j even show color1, odd ones
// color2. A point exactly on a tile border belongs to the tile above it (floor), also for negative
// coordinates: u = -0.25 with tiles_u = 4 is tile -1 (odd). The products are formed in double, where
// float * float is exact, so borders fall exactly where the numbers say.
//
// Parameters
//   tiles_u    tiles per unit of u, > 0                      default 8
//   tiles_v    tiles per unit of v, > 0                      default tiles_u
//   color1     even tiles: a colour or a texture             default 1 (white)
//   color2     odd tiles: a colour or a texture              default 0 (black)
// A colour is one number (grey) or [r, g, b]; a texture is an object (rtlab/textures/texture_param.hpp).
// Nested textures see the unmodified lookup.
#include "texture_params.hpp"

#include <cmath>
#include <cstdint>

namespace rtlab::detail {

namespace {
class CheckerTexture final : public Texture {
public:
    CheckerTexture(double tiles_u, double tiles_v, std::shared_ptr<const Texture> even,
                   std::shared_ptr<const Texture> odd)
        : m_tiles_u(tiles_u), m_tiles_v(tiles_v), m_even(std::move(even)), m_odd(std::move(odd)) {}

    RGB eval(const TextureLookup& q) const override {
        const double i = std::floor(static_cast<double>(q.uv.x) * m_tiles_u);
        const double j = std::floor(static_cast<double>(q.uv.y) * m_tiles_v);
        // Non-finite uv gives no parity, which counts as even.
        const int pi = parity(i), pj = parity(j);
        const bool odd = pi >= 0 && pj >= 0 && pi + pj == 1;
        return (odd ? m_odd : m_even)->eval(q);
    }

private:
    /// |fmod(x, 2)| of an integral x (0 or 1), -1 for a non-finite one. Integers of 2^53 and beyond are all
    /// even doubles; below, the conversion is exact and the low bit is the parity (two's complement keeps it
    /// for negatives). The same answer as fmod, without its cost on every hit of a board.
    static int parity(double x) {
        if (!std::isfinite(x)) return -1;
        if (!(std::abs(x) < 0x1p53)) return 0;
        return static_cast<int>(static_cast<std::int64_t>(x) & 1);
    }

    double m_tiles_u, m_tiles_v;
    std::shared_ptr<const Texture> m_even, m_odd;
};
}  // namespace

namespace {
TypeSpec checker_spec() {
    TypeSpec s("2D checkerboard in uv, tile (floor(u tiles_u), floor(v tiles_v)), even tiles first");
    s.add("tiles_u", ParamKind::number, "tiles per unit u (> 0)").defaults("8").at_least(0);
    s.add("tiles_v", ParamKind::number, "tiles per unit v (> 0; default: tiles_u)").at_least(0);
    add_two_colours(s, "even tiles", "1", "odd tiles", "0");
    return s;
}
}  // namespace

void register_checker(TextureRegistry& registry) {
    registry.add(
        "checker",
        [](const Params& p) -> std::shared_ptr<Texture> {
            const float tu = positive_float(p, "tiles_u", 8.0f);
            const float tv = positive_float(p, "tiles_v", tu);
            return std::make_shared<CheckerTexture>(tu, tv, texture_param(p, "color1", 1.0f),
                                                    texture_param(p, "color2", 0.0f));
        },
        checker_spec());
}

}  // namespace rtlab::detail
