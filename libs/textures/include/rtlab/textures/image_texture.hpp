#pragma once
/// \brief An image looked up by uv: bilinear or nearest filtering, wrap modes, uv scale and offset, and
/// optionally a pyramid of levels looked up at a level of detail (rtlab/textures/mip_map.hpp).
#include <rtlab/core/image.hpp>
#include <rtlab/textures/mip_map.hpp>
#include <rtlab/textures/texture.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace rtlab {

/// What happens outside [0, 1]: repeat the image, clamp to the edge texels, or repeat mirrored.
enum class WrapMode { repeat, clamp, mirror };
enum class ImageFilter { bilinear, nearest };

/// "repeat", "clamp", "mirror"; anything else throws rtlab::Error naming what was given.
WrapMode parse_wrap_mode(std::string_view name);

struct ImageTextureOptions {
    WrapMode wrap = WrapMode::repeat;
    ImageFilter filter = ImageFilter::bilinear;
    Vec2 scale{1.0f};  ///< uv' = uv * scale + offset, then looked up
    Vec2 offset{0.0f};
    std::optional<WrapMode> wrap_v{};  ///< v's wrap when it differs from u's (a planet map: u repeats, v clamps)
    float intensity = 1.0f;            ///< colours are multiplied by it (an emission map's brightness); alpha is not
};

/// \brief Image texture. Texel (x, y) covers u in [x/W, (x+1)/W] and v in [1-(y+1)/H, 1-y/H]: u to the
/// right, v up, so v = 0 is the image's bottom row (the OpenGL / pbrt convention). Bilinear filtering
/// interpolates between texel centres, wrapping the neighbours with the wrap mode. Non-finite uv gives black.
/// An image with an alpha plane (an RGBA file) also answers alpha(), filtered and wrapped the same way.
/// Made from a pyramid (mip_levels()), it looks up the two levels around its lod and blends them
/// (trilinear with bilinear filtering); the lod is 0 until set_lod.
class ImageTexture final : public Texture, public LevelOfDetail {
public:
    /// The image must not be empty. 8-bit files are already linear here (read_image decodes sRGB).
    explicit ImageTexture(std::shared_ptr<const Image> image, const ImageTextureOptions& options = {});
    /// Level 0 first, each level half the size of the one before (as mip_levels() makes them).
    ImageTexture(std::vector<std::shared_ptr<const Image>> levels, const ImageTextureOptions& options);
    /// Loads with rtlab::read_image; a missing or corrupt file throws rtlab::Error naming it.
    static std::shared_ptr<ImageTexture> load(const std::filesystem::path& path,
                                              const ImageTextureOptions& options = {},
                                              ColorEncoding encoding = ColorEncoding::srgb);

    RGB eval(const TextureLookup& lookup) const override { return sample(lookup.uv); }
    bool has_alpha() const override { return image().has_alpha(); }
    float alpha(const TextureLookup& lookup) const override { return sample_alpha(lookup.uv); }
    RGB sample(Vec2 uv) const;
    /// The image's alpha at uv: 1 without an alpha plane; 0 for non-finite uv (nothing there, as the black colour).
    float sample_alpha(Vec2 uv) const;
    const Image& image() const { return *m_levels.front(); }
    int levels() const { return static_cast<int>(m_levels.size()); }

    void set_lod(float lod) override;
    float lod() const override { return m_lod; }
    int texels_u() const override { return image().width(); }

private:
    // The texels a lookup blends: columns c0, c1 and rows r0, r1 (already wrapped) with weights fx, fy;
    // with nearest filtering only (c0, r0).
    struct Footprint {
        int c0, c1, r0, r1;
        float fx, fy;
    };
    bool footprint(const Image& image, Vec2 uv, Footprint& f) const;  // false for non-finite uv
    RGB sample_level(const Image& image, Vec2 uv) const;
    float alpha_level(const Image& image, Vec2 uv) const;

    std::vector<std::shared_ptr<const Image>> m_levels;
    ImageTextureOptions m_options;
    float m_lod = 0.0f;
    LevelBlend m_blend;
};

}  // namespace rtlab
