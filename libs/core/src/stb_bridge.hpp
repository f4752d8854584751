#pragma once
// A narrow, private interface to stb, so image.cpp never sees stb's macros.
#include <vector>

namespace rtlab::stb {
// 8- and 16-bit loads return `channels` (3 or 4) values per pixel.
float* load_float(const unsigned char* data, int size, int* w, int* h);
unsigned char* load_8bit(const unsigned char* data, int size, int* w, int* h, int channels);
unsigned short* load_16bit(const unsigned char* data, int size, int* w, int* h, int channels);
// The number of channels stored in the file (1 to 4), or 0 when stb does not recognise it.
int file_channels(const unsigned char* data, int size);
bool is_hdr(const unsigned char* data, int size);
bool is_16bit(const unsigned char* data, int size);
void free_image(void* pixels);
const char* failure_reason();
bool encode_png(std::vector<unsigned char>& out, int w, int h, int channels, const unsigned char* pixels);
bool encode_hdr(std::vector<unsigned char>& out, int w, int h, const float* rgb);
}  // namespace rtlab::stb
