#pragma once
/// \brief An image looked up by uv: bilinear or nearest filtering, wrap modes, uv scale and offset.
#include <rtlab/core/image.hpp>
#include <rtlab/textures/texture.hpp>

#include <filesystem>
#include <memory>
#include <string_view>

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
};

/// \brief Image texture. Texel (x, y) covers u in [x/W, (x+1)/W] and v in [1-(y+1)/H, 1-y/H]: u to the
/// right, v up, so v = 0 is the image's bottom row (the OpenGL / pbrt convention). Bilinear filtering
/// interpolates between texel centres, wrapping the neighbours with the wrap mode. Non-finite uv gives black.
/// An image with an alpha plane (an RGBA file) also answers alpha(), filtered and wrapped the same way.
class ImageTexture final : public Texture {
public:
    /// The image must not be empty. 8-bit files are already linear here (read_image decodes sRGB).
    explicit ImageTexture(std::shared_ptr<const Image> image, const ImageTextureOptions& options = {});
    /// Loads with rtlab::read_image; a missing or corrupt file throws rtlab::Error naming it.
    static std::shared_ptr<ImageTexture> load(const std::filesystem::path& path,
                                              const ImageTextureOptions& options = {},
                                              ColorEncoding encoding = ColorEncoding::srgb);

    RGB eval(const TextureLookup& lookup) const override { return sample(lookup.uv); }
    bool has_alpha() const override { return m_image->has_alpha(); }
    float alpha(const TextureLookup& lookup) const override { return sample_alpha(lookup.uv); }
    RGB sample(Vec2 uv) const;
    /// The image's alpha at uv: 1 without an alpha plane; 0 for non-finite uv (nothing there, as the black colour).
    float sample_alpha(Vec2 uv) const;
    const Image& image() const { return *m_image; }

private:
    // The texels a lookup blends: columns c0, c1 and rows r0, r1 (already wrapped) with weights fx, fy;
    // with nearest filtering only (c0, r0).
    struct Footprint {
        int c0, c1, r0, r1;
        float fx, fy;
    };
    bool footprint(Vec2 uv, Footprint& f) const;  // false for non-finite uv

    std::shared_ptr<const Image> m_image;
    ImageTextureOptions m_options;
};

}  // namespace rtlab
