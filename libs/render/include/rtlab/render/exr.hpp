#pragma once
/// \brief OpenEXR files with 32-bit float R, G, B channels.
#include <rtlab/core/image.hpp>

#include <filesystem>

namespace rtlab {

/// Writes a scan-line EXR with float R, G, B channels (ZIP compression). Throws rtlab::Error naming the
/// file and the reason when it cannot be written.
void write_exr(const Image& image, const std::filesystem::path& path);

/// Reads an EXR's R, G, B channels as float (a missing channel reads as 0; data window only). Throws
/// rtlab::Error naming the file and the reason.
Image read_exr(const std::filesystem::path& path);

}  // namespace rtlab
