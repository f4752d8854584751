#pragma once
/// \brief Planet maps filtered for the size a planet has on screen: a box-filtered image pyramid and a texture
/// that blends two of its levels (trilinear), picked from the planet's pixel footprint.
#include <rtlab/core/image.hpp>
#include <rtlab/textures/texture.hpp>

#include <memory>
#include <vector>

namespace rtlab::solar {

/// Half the width and height, each output texel the mean of the 2 x 2 (or, at an odd edge, fewer) texels it
/// covers, alpha included. Linear values in, linear values out.
Image downsample(const Image& image);

/// \brief An equirectangular map and its box-filtered levels down to a few texels: level k is
/// 2^k times smaller than level 0 in each direction.
class MipMap {
public:
    explicit MipMap(Image level0);
    int levels() const { return static_cast<int>(m_levels.size()); }
    const Image& level(int k) const { return m_levels[static_cast<std::size_t>(k)]; }
    int width() const { return m_levels.front().width(); }

private:
    std::vector<Image> m_levels;
};

/// The level of detail for an equirectangular map `map_width` texels around, on a sphere `diameter_pixels`
/// wide on screen: at the disc's centre one pixel spans 2 / diameter radians of longitude, which is
/// map_width / (pi diameter) texels; the level makes that one texel. 0 when the map is already coarser.
float planet_lod(int map_width, float diameter_pixels);

/// \brief A MipMap looked up by uv at a fixed level of detail: bilinear in the two levels around `lod`,
/// blended linearly (trilinear filtering). u wraps (longitude), v clamps (the poles), so there is no seam at
/// longitude 180 degrees and no bleeding of one pole into the other. Values are multiplied by `scale`
/// (the Sun's emission). lod < 0 is taken as 0.
class MipTexture final : public Texture {
public:
    MipTexture(std::shared_ptr<const MipMap> map, float lod, float scale = 1.0f);
    RGB eval(const TextureLookup& lookup) const override;

private:
    static RGB bilinear(const Image& image, Vec2 uv);
    std::shared_ptr<const MipMap> m_map;
    int m_level0 = 0, m_level1 = 0;
    float m_blend = 0.0f, m_scale = 1.0f;
};

}  // namespace rtlab::solar
