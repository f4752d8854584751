#include <rtlab/core/cube_face.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/textures/mip_map.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

Image downsample(const Image& image) {
    const int w = std::max(1, image.width() / 2), h = std::max(1, image.height() / 2);
    Image out(w, h);
    if (image.has_alpha()) out.add_alpha();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            RGB sum;
            float alpha = 0.0f;
            for (int dy = 0; dy < 2; ++dy) {
                for (int dx = 0; dx < 2; ++dx) {
                    // An odd last column or row is counted twice rather than dropped.
                    const int sx = std::min(2 * x + dx, image.width() - 1),
                              sy = std::min(2 * y + dy, image.height() - 1);
                    sum += image.at(sx, sy);
                    alpha += image.alpha(sx, sy);
                }
            }
            out.at(x, y) = sum / 4.0f;
            if (out.has_alpha()) out.alpha_at(x, y) = alpha / 4.0f;
        }
    }
    return out;
}

std::vector<std::shared_ptr<const Image>> mip_levels(std::shared_ptr<const Image> level0) {
    if (!level0 || level0->empty()) throw Error("mip levels: the image is empty");
    std::vector<std::shared_ptr<const Image>> levels{std::move(level0)};
    while (levels.back()->width() > 1 || levels.back()->height() > 1)
        levels.push_back(std::make_shared<const Image>(downsample(*levels.back())));
    return levels;
}

LevelBlend level_blend(float lod, int level_count) {
    const float top = static_cast<float>(std::max(level_count, 1) - 1);
    const float l = std::clamp(std::isfinite(lod) ? lod : 0.0f, 0.0f, top);
    LevelBlend b;
    b.first = static_cast<int>(std::floor(l));
    b.second = std::min(b.first + 1, std::max(level_count, 1) - 1);
    b.blend = l - static_cast<float>(b.first);
    return b;
}

Image bake_texture(const Texture& texture, int width, int height) {
    if (width < 1 || height < 1) throw Error("bake: the size must be at least 1 x 1");
    Image out(width, height);
    for (int y = 0; y < height; ++y) {
        const float v = 1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
        const float latitude = kPi * (v - 0.5f);
        for (int x = 0; x < width; ++x) {
            const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
            // Sphere: u = (atan2(-n.z, n.x) + pi) / 2 pi, v = 1 - acos(n.y) / pi.
            const float phi = 2.0f * kPi * u - kPi;
            TextureLookup q;
            q.uv = {u, v};
            q.point = {std::cos(latitude) * std::cos(phi), std::sin(latitude), -std::cos(latitude) * std::sin(phi)};
            q.direction = q.point;
            out.at(x, y) = texture.eval(q);
        }
    }
    return out;
}

std::array<Image, 6> bake_cube_faces(const Texture& texture, int size) {
    if (size < 1) throw Error("bake: the face size must be at least 1");
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) {
        faces[f] = Image(size, size);
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                const float s = (static_cast<float>(x) + 0.5f) / static_cast<float>(size);
                const float t = (static_cast<float>(y) + 0.5f) / static_cast<float>(size);
                TextureLookup q;
                q.direction = cube_face_direction(static_cast<CubeFace>(f), s, t);
                q.point = q.direction;
                q.uv = {s, 1.0f - t};
                faces[f].at(x, y) = texture.eval(q);
            }
        }
    }
    return faces;
}

}  // namespace rtlab
