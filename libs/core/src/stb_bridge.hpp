#pragma once
// A narrow, private interface to stb, so image.cpp never sees stb's macros.
#include <vector>

namespace rtlab::stb {
float* load_float(const unsigned char* data, int size, int* w, int* h);
unsigned char* load_8bit(const unsigned char* data, int size, int* w, int* h);
unsigned short* load_16bit(const unsigned char* data, int size, int* w, int* h);
bool is_hdr(const unsigned char* data, int size);
bool is_16bit(const unsigned char* data, int size);
void free_image(void* pixels);
const char* failure_reason();
bool encode_png(std::vector<unsigned char>& out, int w, int h, const unsigned char* rgb);
bool encode_hdr(std::vector<unsigned char>& out, int w, int h, const float* rgb);
}  // namespace rtlab::stb
