// Texture "image": an image file looked up by uv.
//
// Files: PNG, JPG, BMP, TGA (8-bit, decoded from sRGB to linear unless encoding = "linear"), Radiance HDR
// and PFM (linear floats), all through rtlab::read_image. uv' = uv * scale + offset; u runs to the right
// and v up, so v' = 0 is the bottom row of the file and v' = 1 its top. Texel centres sit at
// ((x + 0.5) / W, 1 - (y + 0.5) / H); bilinear filtering blends the four centres around uv', and the
// wrap mode decides which texels lie beyond the edges: repeat (tile), clamp (edge texels extend) or
// mirror (tile, every other copy flipped). A missing or undecodable file is an error naming the file.
//
// Alpha: a file with an alpha channel (8-bit or 16-bit RGBA or grey + alpha PNG, RGBA TGA) gives the
// texture an alpha, read linearly (never sRGB-decoded) and filtered and wrapped like the colour; other
// files have alpha 1. Materials read opacity through rtlab::opacity(), which uses this alpha, so an RGBA
// image works as a cut-out (Saturn's rings).
//
// Parameters
//   filename   the image file (required)
//   wrap       repeat | clamp | mirror                          default repeat
//   filter     bilinear | nearest                               default bilinear
//   scale      uv multiplier, one number or [su, sv]            default 1
//   offset     added after scaling, one number or [ou, ov]      default 0
//   encoding   srgb | linear: how 8-bit files are decoded       default srgb
//   wrap_v     repeat | clamp | mirror for v alone              default: wrap
//   intensity  colour multiplier >= 0 (alpha is not scaled)     default 1
//   lod        level of detail >= 0: builds the pyramid and     default: no pyramid
//              blends the two levels around it (a scene file's "auto" is worked out by the loader)
//   bake       instead of filename: a texture baked into an image (rtlab::bake_texture) that is then
//   bake_size  used as the file would be; [w, h]                 default [1024, 512]
#include <rtlab/core/error.hpp>
#include <rtlab/textures/image_texture.hpp>

#include "texture_params.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace rtlab {

WrapMode parse_wrap_mode(std::string_view name) {
    if (name == "repeat") return WrapMode::repeat;
    if (name == "clamp") return WrapMode::clamp;
    if (name == "mirror") return WrapMode::mirror;
    throw Error("unknown wrap mode '" + std::string(name) + "' (use repeat, clamp or mirror)");
}

ImageTexture::ImageTexture(std::shared_ptr<const Image> image, const ImageTextureOptions& options)
    : ImageTexture(std::vector<std::shared_ptr<const Image>>{std::move(image)}, options) {}

ImageTexture::ImageTexture(std::vector<std::shared_ptr<const Image>> levels, const ImageTextureOptions& options)
    : m_levels(std::move(levels)), m_options(options) {
    if (m_levels.empty()) throw Error("image texture: no image");
    for (const auto& level : m_levels)
        if (!level || level->empty()) throw Error("image texture: the image is empty");
    set_lod(0.0f);
}

void ImageTexture::set_lod(float lod) {
    m_blend = level_blend(lod, levels());
    m_lod = static_cast<float>(m_blend.first) + m_blend.blend;
}

std::shared_ptr<ImageTexture> ImageTexture::load(const std::filesystem::path& path, const ImageTextureOptions& options,
                                                 ColorEncoding encoding) {
    return std::make_shared<ImageTexture>(std::make_shared<const Image>(read_image(path, encoding)), options);
}

namespace {
// Wraps an integral texel index into [0, n).
int wrap_index(std::int64_t i, int n, WrapMode mode) {
    if (i >= 0 && i < n) return static_cast<int>(i);  // inside: the same for every mode, and no division
    switch (mode) {
        case WrapMode::clamp:
            return static_cast<int>(std::clamp<std::int64_t>(i, 0, n - 1));
        case WrapMode::repeat: {
            const std::int64_t m = i % n;
            return static_cast<int>(m < 0 ? m + n : m);
        }
        case WrapMode::mirror: {
            const std::int64_t period = 2 * static_cast<std::int64_t>(n);
            std::int64_t m = i % period;
            if (m < 0) m += period;
            return static_cast<int>(m < n ? m : period - 1 - m);
        }
    }
    return 0;
}

// Brings a floored texel coordinate into int64 range without changing what it wraps to: fmod by 2n
// (exact) keeps both the repeat period n and the mirror period 2n; clamp only needs [-1, n].
std::int64_t reduce(double i, int n, WrapMode mode) {
    if (std::abs(i) < 0x1p40) return static_cast<std::int64_t>(i);
    if (mode == WrapMode::clamp) return i < 0.0 ? -1 : n;
    return static_cast<std::int64_t>(std::fmod(i, 2.0 * n));
}
}  // namespace

bool ImageTexture::footprint(const Image& img, Vec2 uv, Footprint& f) const {
    const double u = static_cast<double>(uv.x) * m_options.scale.x + m_options.offset.x;
    const double v = static_cast<double>(uv.y) * m_options.scale.y + m_options.offset.y;
    if (!std::isfinite(u) || !std::isfinite(v)) return false;
    // Continuous texel coordinates, row 0 at the top: texel centres at integers.
    const double x = u * img.width() - 0.5;
    const double y = (1.0 - v) * img.height() - 0.5;
    const WrapMode wrap = m_options.wrap, wrap_v = m_options.wrap_v.value_or(m_options.wrap);
    if (m_options.filter == ImageFilter::nearest) {
        f.c0 = wrap_index(reduce(std::floor(x + 0.5), img.width(), wrap), img.width(), wrap);
        f.r0 = wrap_index(reduce(std::floor(y + 0.5), img.height(), wrap_v), img.height(), wrap_v);
        return true;
    }
    const double xf = std::floor(x), yf = std::floor(y);
    f.fx = static_cast<float>(x - xf), f.fy = static_cast<float>(y - yf);
    const std::int64_t x0 = reduce(xf, img.width(), wrap), y0 = reduce(yf, img.height(), wrap_v);
    f.c0 = wrap_index(x0, img.width(), wrap), f.c1 = wrap_index(x0 + 1, img.width(), wrap);
    f.r0 = wrap_index(y0, img.height(), wrap_v), f.r1 = wrap_index(y0 + 1, img.height(), wrap_v);
    return true;
}

RGB ImageTexture::sample_level(const Image& img, Vec2 uv) const {
    Footprint f;
    if (!footprint(img, uv, f)) return {};
    if (m_options.filter == ImageFilter::nearest) return img.at(f.c0, f.r0);
    const RGB top = lerp(img.at(f.c0, f.r0), img.at(f.c1, f.r0), f.fx);
    const RGB bottom = lerp(img.at(f.c0, f.r1), img.at(f.c1, f.r1), f.fx);
    return lerp(top, bottom, f.fy);
}

RGB ImageTexture::sample(Vec2 uv) const {
    RGB c = sample_level(*m_levels[static_cast<std::size_t>(m_blend.first)], uv);
    if (m_blend.blend > 0.0f)
        c = lerp(c, sample_level(*m_levels[static_cast<std::size_t>(m_blend.second)], uv), m_blend.blend);
    return m_options.intensity == 1.0f ? c : c * m_options.intensity;
}

float ImageTexture::sample_alpha(Vec2 uv) const {
    if (!image().has_alpha()) return 1.0f;
    const float a = alpha_level(*m_levels[static_cast<std::size_t>(m_blend.first)], uv);
    if (!(m_blend.blend > 0.0f)) return a;
    const float b = alpha_level(*m_levels[static_cast<std::size_t>(m_blend.second)], uv);
    return a * (1.0f - m_blend.blend) + b * m_blend.blend;
}

float ImageTexture::alpha_level(const Image& img, Vec2 uv) const {
    Footprint f;
    if (!footprint(img, uv, f)) return 0.0f;
    if (m_options.filter == ImageFilter::nearest) return img.alpha(f.c0, f.r0);
    // The same weights and order of operations as the colour, so an opaque region (alpha 1) stays exactly 1.
    const auto mix = [](float a, float b, float t) { return a * (1.0f - t) + b * t; };
    const float top = mix(img.alpha(f.c0, f.r0), img.alpha(f.c1, f.r0), f.fx);
    const float bottom = mix(img.alpha(f.c0, f.r1), img.alpha(f.c1, f.r1), f.fx);
    return mix(top, bottom, f.fy);
}

namespace detail {

namespace {
TypeSpec image_spec() {
    TypeSpec s("image file by uv (v up: v = 0 is the bottom row), bilinear filtering");
    s.add("filename", ParamKind::file, "the image (PNG, JPEG, ...; required unless bake)");
    const std::vector<std::string> wraps{"repeat", "clamp", "mirror"};
    s.add("wrap", ParamKind::word, "what lies outside [0, 1]").defaults("repeat").allow(wraps);
    s.add("wrap_v", ParamKind::word, "v's own wrap (default: wrap)").allow(wraps);
    s.add("filter", ParamKind::word, "between texels").defaults("bilinear").allow({"bilinear", "nearest"});
    s.add("scale", ParamKind::numbers, "uv multiplier, [su, sv] or one number").defaults("1");
    s.add("offset", ParamKind::numbers, "added to uv after scale, [ou, ov] or one number").defaults("0");
    add_image_options(s, "[width, height] of the baked image, whole numbers in 1..16384", "[1024, 512]");
    return s;
}
}  // namespace

void register_image(TextureRegistry& registry) {
    registry.add(
        "image",
        [](const Params& p) -> std::shared_ptr<Texture> {
            ImageTextureOptions o;
            o.wrap = parse_wrap_mode(one_of(p, "wrap", "repeat", {"repeat", "clamp", "mirror"}));
            if (p.has("wrap_v"))
                o.wrap_v = parse_wrap_mode(one_of(p, "wrap_v", "repeat", {"repeat", "clamp", "mirror"}));
            o.intensity = positive_float(p, "intensity", 1.0f, true);
            o.filter = one_of(p, "filter", "bilinear", {"bilinear", "nearest"}) == "bilinear" ? ImageFilter::bilinear
                                                                                              : ImageFilter::nearest;
            o.scale = get_vec2(p, "scale", Vec2(1.0f));
            o.offset = get_vec2(p, "offset", Vec2(0.0f));
            const ColorEncoding encoding = get_encoding(p);
            // Without "lod", no pyramid (a plain float: GCC 12 warns falsely on an optional here).
            const bool levelled = p.has("lod");
            const float lod = levelled ? float_in_range(p, "lod", 0.0f, 0.0f, 64.0f) : 0.0f;
            if (p.has("filename") && p.has("bake"))
                throw Error(p.context() + ": give 'filename' or 'bake' (a texture to bake), not both");
            std::shared_ptr<const Image> image;
            if (p.has("bake")) {
                const auto texture = p.get_object<Texture>("bake");
                const Params::List size = p.has("bake_size") ? p.get_list("bake_size") : Params::List{1024.0, 512.0};
                if (size.size() != 2 || !(size[0] >= 1.0 && size[0] <= 16384.0) ||
                    !(size[1] >= 1.0 && size[1] <= 16384.0) || size[0] != std::floor(size[0]) ||
                    size[1] != std::floor(size[1]))
                    fail_param(p, "bake_size", "must be [width, height], whole numbers in 1..16384");
                if (!texture) fail_param(p, "bake", "must be a texture");
                image = std::make_shared<const Image>(
                    bake_texture(*texture, static_cast<int>(size[0]), static_cast<int>(size[1])));
            } else {
                if (p.has("bake_size")) fail_param(p, "bake_size", "is only used with 'bake'");
                const std::string filename = p.get_string("filename");
                try {
                    image = std::make_shared<const Image>(read_image(filename, encoding));
                } catch (const Error& e) {
                    throw Error(p.context() + ": " + e.what());
                }
            }
            if (!levelled) return std::make_shared<ImageTexture>(std::move(image), o);
            auto texture = std::make_shared<ImageTexture>(mip_levels(std::move(image)), o);
            texture->set_lod(lod);
            return texture;
        },
        image_spec());
}

}  // namespace detail
}  // namespace rtlab
