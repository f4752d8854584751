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
    return stbi_write_png_to_func(append, &out, w, h, channels, pixels, w * channels) != 0;
}
bool encode_hdr(std::vector<unsigned char>& out, int w, int h, const float* rgb) {
    return stbi_write_hdr_to_func(append, &out, w, h, 3, rgb) != 0;
}

}  // namespace rtlab::stb
