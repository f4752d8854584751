// Texture "checker3d": a solid (3D) checkerboard in object space, read from lookup.point.
//
// Cell (i, j, k) = floor(point * tiles); cells with i + j + k even show color1, odd ones color2. Points
// on a cell face belong to the cell above them, as in "checker".
//
// Parameters
//   tiles      cells per unit length, one number or [x, y, z], > 0   default 1
//   color1     even cells: a colour or a texture                     default 1 (white)
//   color2     odd cells: a colour or a texture                      default 0 (black)
// A colour is one number (grey) or [r, g, b]; a texture is an object (rtlab/textures/texture_param.hpp).
// Nested textures see the unmodified lookup.
#include "texture_params.hpp"

#include <cmath>

namespace rtlab::detail {

namespace {
class Checker3dTexture final : public Texture {
public:
    Checker3dTexture(const Vec3& tiles, std::shared_ptr<const Texture> even, std::shared_ptr<const Texture> odd)
        : m_tiles(tiles), m_even(std::move(even)), m_odd(std::move(odd)) {}

    RGB eval(const TextureLookup& q) const override {
        double parity = 0.0;
        for (int a = 0; a < 3; ++a)
            parity += std::abs(std::fmod(std::floor(static_cast<double>(q.point[a]) * m_tiles[a]), 2.0));
        return (std::fmod(parity, 2.0) == 1.0 ? m_odd : m_even)->eval(q);
    }

private:
    glm::dvec3 m_tiles;
    std::shared_ptr<const Texture> m_even, m_odd;
};
}  // namespace

namespace {
TypeSpec checker3d_spec() {
    TypeSpec s("solid 3D checkerboard in object space (lookup.point), cell floor(point tiles), even cells first");
    s.add("tiles", ParamKind::numbers, "cells per unit, one number or [x, y, z], each > 0").defaults("1");
    add_two_colours(s, "even cells", "1", "odd cells", "0");
    return s;
}
}  // namespace

void register_checker3d(TextureRegistry& registry) {
    registry.add(
        "checker3d",
        [](const Params& p) -> std::shared_ptr<Texture> {
            Vec3 tiles(1.0f);
            if (p.has("tiles")) {
                const Params::List l = p.get_list("tiles");
                if (l.size() != 1 && l.size() != 3) fail_param(p, "tiles", "must be one number or a list of 3");
                for (int a = 0; a < 3; ++a) tiles[a] = static_cast<float>(l.size() == 1 ? l[0] : l[a]);
                for (int a = 0; a < 3; ++a)
                    if (!(std::isfinite(tiles[a]) && tiles[a] > 0.0f)) fail_param(p, "tiles", "must be finite and > 0");
            }
            return std::make_shared<Checker3dTexture>(tiles, texture_param(p, "color1", 1.0f),
                                                      texture_param(p, "color2", 0.0f));
        },
        checker3d_spec());
}

}  // namespace rtlab::detail
