#pragma once
/// \brief Float HDR RGB image with an optional alpha plane, and its file formats (PNG, JPG, HDR, PFM).
#include <rtlab/core/color.hpp>

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

namespace rtlab {

/// \brief Row-major float RGB image; pixel (0, 0) is the top-left corner. It may carry an alpha plane
/// (straight, not premultiplied; linear, never sRGB-encoded); without one, alpha is 1 everywhere.
class Image {
public:
    Image() = default;
    Image(int width, int height, RGB fill = {});

    int width() const { return m_width; }
    int height() const { return m_height; }
    bool empty() const { return m_pixels.empty(); }
    std::size_t pixel_count() const { return m_pixels.size(); }

    RGB& at(int x, int y) { return m_pixels[index(x, y)]; }
    const RGB& at(int x, int y) const { return m_pixels[index(x, y)]; }
    std::span<RGB> pixels() { return m_pixels; }
    std::span<const RGB> pixels() const { return m_pixels; }

    bool has_alpha() const { return !m_alpha.empty(); }
    /// Gives the image an alpha plane filled with `fill`; an existing plane is kept as it is.
    void add_alpha(float fill = 1.0f);
    /// The alpha of pixel (x, y): 1 without an alpha plane.
    float alpha(int x, int y) const { return m_alpha.empty() ? 1.0f : m_alpha[index(x, y)]; }
    /// Writable alpha of pixel (x, y); the image must have an alpha plane (add_alpha).
    float& alpha_at(int x, int y) { return m_alpha[index(x, y)]; }
    /// The alpha plane in pixel order; empty without one.
    std::span<const float> alphas() const { return m_alpha; }

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(m_width) + static_cast<std::size_t>(x);
    }

    int m_width = 0;
    int m_height = 0;
    std::vector<RGB> m_pixels;
    std::vector<float> m_alpha;  // empty, or one value per pixel
};

/// How 8-bit files are turned into linear values on reading.
enum class ColorEncoding { srgb, linear };

/// Reads PNG, JPG, BMP, TGA (8-bit, decoded from sRGB unless told otherwise), Radiance HDR and PFM.
/// Files with an alpha channel (grey + alpha, RGBA) give an image with an alpha plane, read linearly
/// (code / 255 or / 65535) whatever the encoding. Throws rtlab::Error naming the file and the reason
/// when it cannot be read; for an OpenEXR file the reason says that rtlab::render reads it
/// (rtlab/render/image_input.hpp), which keeps OpenEXR out of core's dependencies.
Image read_image(const std::filesystem::path& path, ColorEncoding encoding = ColorEncoding::srgb);

/// Writes by extension: .png (8-bit, sRGB-encoded, clamped to [0, 1]; RGBA with linear alpha when the
/// image has an alpha plane), .hdr (Radiance RGBE) or .pfm (both without alpha).
/// Throws rtlab::Error naming the file and the reason when it cannot be written.
void write_image(const Image& image, const std::filesystem::path& path);

void write_png(const Image& image, const std::filesystem::path& path);
void write_hdr(const Image& image, const std::filesystem::path& path);
void write_pfm(const Image& image, const std::filesystem::path& path);
Image read_pfm(const std::filesystem::path& path);

}  // namespace rtlab
