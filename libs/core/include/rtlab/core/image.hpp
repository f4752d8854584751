#pragma once
/// \brief Float HDR RGB image and its file formats (PNG, JPG, HDR, PFM).
#include <rtlab/core/color.hpp>

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

namespace rtlab {

/// \brief Row-major float RGB image; pixel (0, 0) is the top-left corner.
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

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(m_width) + static_cast<std::size_t>(x);
    }

    int m_width = 0;
    int m_height = 0;
    std::vector<RGB> m_pixels;
};

/// How 8-bit files are turned into linear values on reading.
enum class ColorEncoding { srgb, linear };

/// Reads PNG, JPG, BMP, TGA (8-bit, decoded from sRGB unless told otherwise), Radiance HDR and PFM.
/// Throws rtlab::Error naming the file and the reason when it cannot be read.
Image read_image(const std::filesystem::path& path, ColorEncoding encoding = ColorEncoding::srgb);

/// Writes by extension: .png (8-bit, sRGB-encoded, clamped to [0, 1]), .hdr (Radiance RGBE) or .pfm.
/// Throws rtlab::Error naming the file and the reason when it cannot be written.
void write_image(const Image& image, const std::filesystem::path& path);

void write_png(const Image& image, const std::filesystem::path& path);
void write_hdr(const Image& image, const std::filesystem::path& path);
void write_pfm(const Image& image, const std::filesystem::path& path);
Image read_pfm(const std::filesystem::path& path);

}  // namespace rtlab
