#pragma once
/// \brief OpenEXR files with 32-bit float R, G, B channels.
#include <rtlab/core/image.hpp>

#include <filesystem>
#include <string>

namespace rtlab {

/// Writes a scan-line EXR with float R, G, B channels (ZIP compression); with `variance` (the same size) also
/// float channels variance.R, variance.G, variance.B (a layer named "variance", as EXR viewers group them). Throws
/// rtlab::Error naming the file and the reason when it cannot be written.
void write_exr(const Image& image, const std::filesystem::path& path, const Image* variance = nullptr);

/// Reads the channels LAYER.R, LAYER.G, LAYER.B of an EXR (`layer` empty: R, G, B); a missing channel reads as 0.
Image read_exr_layer(const std::filesystem::path& path, const std::string& layer);

/// Reads an EXR's R, G, B channels as float (a missing channel reads as 0; data window only). Throws
/// rtlab::Error naming the file and the reason.
Image read_exr(const std::filesystem::path& path);

}  // namespace rtlab
