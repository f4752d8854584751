#pragma once
// Whether a PNG or Radiance HDR file holds all the bytes its own structure announces. stb reads past the end
// of its buffer as zeros, so a file cut short decodes to a partly black image without an error (or, for a
// run-length HDR cut inside a scanline, never stops reading); these checks run before stb sees the bytes.
#include <filesystem>
#include <vector>

namespace rtlab::detail {

/// Throws rtlab::Error naming path and saying where the file is truncated, when bytes is a PNG or a
/// Radiance HDR file that ends before its last chunk or scanline does. Other formats, and headers these
/// checks cannot parse, are left to the decoder to judge.
void check_not_truncated(const std::vector<unsigned char>& bytes, const std::filesystem::path& path);

}  // namespace rtlab::detail
