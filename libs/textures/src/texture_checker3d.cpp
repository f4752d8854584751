// Texture "checker3d": a solid (3D) checkerboard in object space, read from lookup.point.
//
// Cell (i, j, k) = floor(point * tiles); cells with i + j + k even show the first colour (or texture),
// odd ones the second. Points on a cell face belong to the cell above them, as in "checker".
//
// Parameters
//   tiles      cells per unit length, one number or [x, y, z], > 0   default 1
//   color1     colour of even cells                                  default 1 (white)
//   color2     colour of odd cells                                   default 0 (black)
//   texture1   nested texture for even cells (instead of color1)
//   texture2   nested texture for odd cells (instead of color2)
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
            return std::make_shared<Checker3dTexture>(tiles, colour_or_texture(p, "color1", "texture1", RGB(1.0f)),
                                                      colour_or_texture(p, "color2", "texture2", RGB(0.0f)));
        },
        "solid 3D checkerboard in object space (lookup.point), cell floor(point tiles), even cells first. "
        "tiles: cells per unit, number or [x, y, z] (default 1); color1 (default 1) or texture1; "
        "color2 (default 0) or texture2");
}

}  // namespace rtlab::detail
