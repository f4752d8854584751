// The one translation unit that compiles stb_image and stb_image_write (single-header libraries from
// Debian's libstb-dev); kept private so no stb symbol or macro leaks into rtlab's public headers.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#include <zlib.h>

#include <cstdlib>

namespace {

// stb_image_write's own deflate (hash chains, one fixed-Huffman block) cost 1.03 G instructions of 1.16 G for a
// 1280x960 bunny render's PNG (callgrind), and its level barely matters: level 5, its lowest, saved 12% for a
// file 2% larger. zlib at level 1 with run-length matching, after the Sub filter on every row (below), wrote the
// same image in 0.15 G and 17% smaller (310,800 -> 257,512 bytes; the Whitted scene 189,046 -> 152,572).
// Returns memory from malloc, as stb frees it with free; nullptr makes stb report the failure.
unsigned char* zlib_compress(unsigned char* data, int size, int* out_size, int /*stb's quality*/) {
    z_stream stream{};
    if (deflateInit2(&stream, 1, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK) return nullptr;
    const uLong capacity = deflateBound(&stream, static_cast<uLong>(size));
    auto* out = static_cast<unsigned char*>(std::malloc(capacity));
    bool ok = out != nullptr;
    if (ok) {
        stream.next_in = data;
        stream.avail_in = static_cast<uInt>(size);
        stream.next_out = out;
        stream.avail_out = static_cast<uInt>(capacity);
        ok = deflate(&stream, Z_FINISH) == Z_STREAM_END;
    }
    *out_size = static_cast<int>(stream.total_out);
    deflateEnd(&stream);
    if (!ok) {
        std::free(out);
        return nullptr;
    }
    return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS zlib_compress
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_FAILURE_USERMSG
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "stb_bridge.hpp"

namespace rtlab::stb {

float* load_float(const unsigned char* data, int size, int* w, int* h) {
    int channels = 0;
    return stbi_loadf_from_memory(data, size, w, h, &channels, 3);
}
unsigned char* load_8bit(const unsigned char* data, int size, int* w, int* h, int channels) {
    int in_file = 0;
    return stbi_load_from_memory(data, size, w, h, &in_file, channels);
}
unsigned short* load_16bit(const unsigned char* data, int size, int* w, int* h, int channels) {
    int in_file = 0;
    return stbi_load_16_from_memory(data, size, w, h, &in_file, channels);
}
int file_channels(const unsigned char* data, int size) {
    int w = 0, h = 0, channels = 0;
    return stbi_info_from_memory(data, size, &w, &h, &channels) ? channels : 0;
}
bool is_hdr(const unsigned char* data, int size) { return stbi_is_hdr_from_memory(data, size) != 0; }
bool is_16bit(const unsigned char* data, int size) { return stbi_is_16_bit_from_memory(data, size) != 0; }
void free_image(void* pixels) { stbi_image_free(pixels); }
const char* failure_reason() { return stbi_failure_reason(); }

namespace {
void append(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}
}  // namespace

bool encode_png(std::vector<unsigned char>& out, int w, int h, int channels, const unsigned char* pixels) {
    // stb tries all five PNG filters on every row and keeps the one with the smallest sum: 0.45 G of the 0.59 G
    // instructions the bunny PNG took with zlib. The Sub filter alone takes 0.15 G for a file 14% larger than the
    // choice gives (257,512 against 225,950 bytes), still 17% smaller than stb's deflate made. Set once: the
    // variable is global to stb.
    static const bool sub_filter = [] {
        stbi_write_force_png_filter = 1;
        return true;
    }();
    (void)sub_filter;
    return stbi_write_png_to_func(append, &out, w, h, channels, pixels, w * channels) != 0;
}
bool encode_hdr(std::vector<unsigned char>& out, int w, int h, const float* rgb) {
    return stbi_write_hdr_to_func(append, &out, w, h, 3, rgb) != 0;
}

}  // namespace rtlab::stb
