#include "planet_map.hpp"

#include <rtlab/core/error.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab::solar {

Image downsample(const Image& image) {
    const int w = std::max(1, image.width() / 2), h = std::max(1, image.height() / 2);
    Image out(w, h);
    if (image.has_alpha()) out.add_alpha();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            RGB sum;
            float alpha = 0.0f;
            int n = 0;
            for (int dy = 0; dy < 2; ++dy) {
                for (int dx = 0; dx < 2; ++dx) {
                    const int sx = std::min(2 * x + dx, image.width() - 1),
                              sy = std::min(2 * y + dy, image.height() - 1);
                    sum += image.at(sx, sy);
                    alpha += image.alpha(sx, sy);
                    ++n;
                }
            }
            out.at(x, y) = sum / static_cast<float>(n);
            if (out.has_alpha()) out.alpha_at(x, y) = alpha / static_cast<float>(n);
        }
    }
    return out;
}

MipMap::MipMap(Image level0) {
    if (level0.empty()) throw Error("mip map: empty image");
    m_levels.push_back(std::move(level0));
    // Down to a map a few texels high: coarser levels would only smear the poles together.
    while (m_levels.back().height() > 2) m_levels.push_back(downsample(m_levels.back()));
}

float planet_lod(int map_width, float diameter_pixels) {
    if (!(diameter_pixels > 0.0f)) return 0.0f;
    const float texels_per_pixel = static_cast<float>(map_width) / (kPi * diameter_pixels);
    return std::max(0.0f, std::log2(texels_per_pixel));
}

MipTexture::MipTexture(std::shared_ptr<const MipMap> map, float lod, float scale)
    : m_map(std::move(map)), m_scale(scale) {
    if (!m_map) throw Error("mip texture: no map");
    const float top = static_cast<float>(m_map->levels() - 1);
    const float l = std::clamp(std::isfinite(lod) ? lod : 0.0f, 0.0f, top);
    m_level0 = static_cast<int>(std::floor(l));
    m_level1 = std::min(m_level0 + 1, m_map->levels() - 1);
    m_blend = l - static_cast<float>(m_level0);
}

RGB MipTexture::bilinear(const Image& image, Vec2 uv) {
    const int w = image.width(), h = image.height();
    // Texel centres at (i + 0.5) / w; v = 0 is the bottom row (TextureLookup's convention).
    const float x = uv.x * static_cast<float>(w) - 0.5f;
    const float y = (1.0f - uv.y) * static_cast<float>(h) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    auto column = [w](float c) {
        const int i = static_cast<int>(c) % w;
        return i < 0 ? i + w : i;
    };
    const int c0 = column(fx), c1 = column(fx + 1.0f);
    const int r0 = std::clamp(static_cast<int>(fy), 0, h - 1), r1 = std::clamp(static_cast<int>(fy) + 1, 0, h - 1);
    const RGB top = image.at(c0, r0) * (1.0f - tx) + image.at(c1, r0) * tx;
    const RGB bottom = image.at(c0, r1) * (1.0f - tx) + image.at(c1, r1) * tx;
    return top * (1.0f - ty) + bottom * ty;
}

RGB MipTexture::eval(const TextureLookup& lookup) const {
    const Vec2 uv = lookup.uv;
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return {};
    const Vec2 wrapped(uv.x - std::floor(uv.x), std::clamp(uv.y, 0.0f, 1.0f));
    RGB c = bilinear(m_map->level(m_level0), wrapped);
    if (m_blend > 0.0f) c = c * (1.0f - m_blend) + bilinear(m_map->level(m_level1), wrapped) * m_blend;
    return c * m_scale;
}

}  // namespace rtlab::solar
