#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/core/srgb.hpp>

#include "stb_bridge.hpp"
#include "truncation_check.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace rtlab {

namespace {

constexpr int kMaxDimension = 1 << 16;

std::string lowercase_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
    throw Error(file_error_message(path, reason));
}

// The PFM header is three whitespace-separated tokens after the "PF" line: width, height, scale.
class HeaderReader {
public:
    HeaderReader(const std::vector<unsigned char>& bytes, const std::filesystem::path& path)
        : m_bytes(bytes), m_path(path) {}

    std::string token() {
        while (m_pos < m_bytes.size() && std::isspace(m_bytes[m_pos])) ++m_pos;
        const std::size_t start = m_pos;
        while (m_pos < m_bytes.size() && !std::isspace(m_bytes[m_pos]) && m_pos - start < 64) ++m_pos;
        if (start == m_pos) fail(m_path, "truncated PFM header");
        return {reinterpret_cast<const char*>(m_bytes.data()) + start, m_pos - start};
    }
    // Exactly one whitespace byte separates the header from the raster.
    std::size_t raster_offset() const { return m_pos + 1; }

private:
    const std::vector<unsigned char>& m_bytes;
    const std::filesystem::path& m_path;
    std::size_t m_pos = 0;
};

template <class T>
T parse_number(const std::string& s, const std::filesystem::path& path, const char* what) {
    T value{};
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec != std::errc() || end != s.data() + s.size())
        fail(path, std::string("PFM header: bad ") + what + " '" + s + "'");
    return value;
}

Image decode_pfm(const std::vector<unsigned char>& bytes, const std::filesystem::path& path) {
    HeaderReader header(bytes, path);
    const std::string magic = header.token();
    if (magic != "PF" && magic != "Pf") fail(path, "not a PFM file (magic '" + magic + "')");
    const int channels = magic == "PF" ? 3 : 1;
    const int w = parse_number<int>(header.token(), path, "width");
    const int h = parse_number<int>(header.token(), path, "height");
    const float scale = parse_number<float>(header.token(), path, "scale");
    if (w <= 0 || h <= 0 || w > kMaxDimension || h > kMaxDimension)
        fail(path, "PFM header: unsupported size " + std::to_string(w) + "x" + std::to_string(h));
    if (scale == 0.0f || !std::isfinite(scale)) fail(path, "PFM header: scale must be finite and non-zero");
    const bool little_endian = scale < 0.0f;
    const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * channels;
    const std::size_t offset = header.raster_offset();
    if (offset > bytes.size() || bytes.size() - offset < count * 4)
        fail(path, "truncated PFM raster: expected " + std::to_string(count * 4) + " bytes");
    Image image(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            float c[3];
            for (int k = 0; k < channels; ++k) {
                // PFM stores rows bottom to top.
                const std::size_t i = ((static_cast<std::size_t>(h - 1 - y) * w + x) * channels + k) * 4;
                std::uint32_t bits;
                std::memcpy(&bits, bytes.data() + offset + i, 4);
                if ((std::endian::native == std::endian::little) != little_endian) bits = __builtin_bswap32(bits);
                c[k] = std::bit_cast<float>(bits);
            }
            image.at(x, y) = channels == 3 ? RGB(c[0], c[1], c[2]) : RGB(c[0]);
        }
    }
    return image;
}

// data holds `channels` (3, or 4 with alpha) values per pixel; colour goes through to_linear, alpha is
// divided by alpha_max only (it is coverage, never sRGB-encoded), so the full code gives exactly 1.
template <class T>
Image copy_pixels(const T* data, int w, int h, int channels, float alpha_max, auto&& to_linear) {
    Image image(w, h);
    if (channels == 4) image.add_alpha();
    auto pixels = image.pixels();
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const T* p = data + static_cast<std::size_t>(channels) * i;
        pixels[i] = RGB(to_linear(p[0]), to_linear(p[1]), to_linear(p[2]));
    }
    if (channels == 4) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                image.alpha_at(x, y) =
                    static_cast<float>(data[4 * (static_cast<std::size_t>(y) * w + x) + 3]) / alpha_max;
    }
    return image;
}

}  // namespace

Image::Image(int width, int height, RGB fill) : m_width(width), m_height(height) {
    if (width < 0 || height < 0) throw Error("image size must not be negative");
    m_pixels.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
}

void Image::add_alpha(float fill) {
    if (m_alpha.empty()) m_alpha.assign(m_pixels.size(), fill);
}

Image read_pfm(const std::filesystem::path& path) { return decode_pfm(read_binary_file(path), path); }

Image read_image(const std::filesystem::path& path, ColorEncoding encoding) {
    const std::vector<unsigned char> bytes = read_binary_file(path);
    if (bytes.empty()) fail(path, "empty file");
    if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == 'F' || bytes[1] == 'f')) return decode_pfm(bytes, path);
    if (bytes.size() >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01)
        fail(path,
             "an OpenEXR file, which rtlab::core does not read (it reads PNG, JPG, BMP, TGA, HDR and PFM); "
             "rtlab::render reads EXR (read_image_file, read_exr), as a scene's environment does");
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) fail(path, "image file too large");
    detail::check_not_truncated(bytes, path);
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0;
    auto check = [&](void* pixels) {
        if (!pixels) fail(path, std::string("cannot decode image: ") + stb::failure_reason());
    };
    if (stb::is_hdr(bytes.data(), size)) {
        float* data = stb::load_float(bytes.data(), size, &w, &h);
        check(data);
        Image image = copy_pixels(data, w, h, 3, 1.0f, [](float v) { return v; });
        stb::free_image(data);
        return image;
    }
    const bool srgb = encoding == ColorEncoding::srgb;
    // Grey + alpha and RGBA files keep their alpha; stb expands grey to RGB.
    const int in_file = stb::file_channels(bytes.data(), size);
    const int channels = in_file == 2 || in_file == 4 ? 4 : 3;
    if (stb::is_16bit(bytes.data(), size)) {
        unsigned short* data = stb::load_16bit(bytes.data(), size, &w, &h, channels);
        check(data);
        Image image = copy_pixels(data, w, h, channels, 65535.0f, [srgb](unsigned short v) {
            const float f = static_cast<float>(v) / 65535.0f;
            return srgb ? srgb_decode(f) : f;
        });
        stb::free_image(data);
        return image;
    }
    unsigned char* data = stb::load_8bit(bytes.data(), size, &w, &h, channels);
    check(data);
    Image image = copy_pixels(data, w, h, channels, 255.0f, [srgb](unsigned char v) {
        return srgb ? srgb_decode_8bit(v) : static_cast<float>(v) / 255.0f;
    });
    stb::free_image(data);
    return image;
}

void write_png(const Image& image, const std::filesystem::path& path) {
    if (image.empty()) fail(path, "cannot write an empty image");
    const int channels = image.has_alpha() ? 4 : 3;
    std::vector<unsigned char> bytes;
    if (channels == 3) {
        bytes.resize(image.pixel_count() * 3);
        srgb_encode_8bit(image.pixels().data(), image.pixels().size(), bytes.data());
    } else {
        bytes.reserve(image.pixel_count() * channels);
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                for (int k = 0; k < 3; ++k) bytes.push_back(srgb_encode_8bit(image.at(x, y)[k]));
                const float a = image.alpha(x, y);  // linear; NaN is written as 0, like colour
                bytes.push_back(a >= 0.0f ? static_cast<unsigned char>(std::lround(std::min(a, 1.0f) * 255.0f)) : 0);
            }
        }
    }
    std::vector<unsigned char> encoded;
    if (!stb::encode_png(encoded, image.width(), image.height(), channels, bytes.data()))
        fail(path, "PNG encoding failed");
    write_binary_file(path, encoded);
}

void write_hdr(const Image& image, const std::filesystem::path& path) {
    if (image.empty()) fail(path, "cannot write an empty image");
    std::vector<float> rgb;
    rgb.reserve(image.pixel_count() * 3);
    for (const RGB& p : image.pixels())
        for (int k = 0; k < 3; ++k) rgb.push_back(std::isfinite(p[k]) ? std::max(p[k], 0.0f) : 0.0f);
    std::vector<unsigned char> encoded;
    if (!stb::encode_hdr(encoded, image.width(), image.height(), rgb.data())) fail(path, "HDR encoding failed");
    write_binary_file(path, encoded);
}

void write_pfm(const Image& image, const std::filesystem::path& path) {
    if (image.empty()) fail(path, "cannot write an empty image");
    const bool little = std::endian::native == std::endian::little;
    const std::string header = "PF\n" + std::to_string(image.width()) + " " + std::to_string(image.height()) + "\n" +
                               (little ? "-1.0" : "1.0") + "\n";
    std::vector<unsigned char> bytes(header.begin(), header.end());
    bytes.reserve(header.size() + image.pixel_count() * 12);
    for (int y = image.height() - 1; y >= 0; --y) {
        for (int x = 0; x < image.width(); ++x) {
            const RGB& p = image.at(x, y);
            for (int k = 0; k < 3; ++k) {
                unsigned char b[4];
                const float v = p[k];
                std::memcpy(b, &v, 4);
                bytes.insert(bytes.end(), b, b + 4);
            }
        }
    }
    write_binary_file(path, bytes);
}

void write_image(const Image& image, const std::filesystem::path& path) {
    const std::string ext = lowercase_extension(path);
    if (ext == ".png") return write_png(image, path);
    if (ext == ".hdr") return write_hdr(image, path);
    if (ext == ".pfm") return write_pfm(image, path);
    fail(path, "unknown image extension '" + ext + "' (use .png, .hdr or .pfm)");
}

}  // namespace rtlab
