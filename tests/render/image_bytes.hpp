#pragma once
// Byte-identity of two images: the check of every "the same image for any thread count, order or path" test.
#include <rtlab/core/image.hpp>

#include <cstring>

namespace rtlab::test {

inline bool same_bytes(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixel_count() * sizeof(RGB)) == 0;
}

}  // namespace rtlab::test
