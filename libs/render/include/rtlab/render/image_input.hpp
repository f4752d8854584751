#pragma once
/// \brief Reading every image format rtlab reads: OpenEXR beside core's PNG, JPG, BMP, TGA, HDR and PFM.
///
/// Why here: core reads its formats through stb and depends on nothing else, and a project that takes only the
/// kd-tree should not need OpenEXR; render already depends on OpenEXR (privately, for its EXR output), and
/// dependencies run one way. So the reader that knows both lives in render, and what needs EXR input (a scene's
/// environment map) is loaded in render or above it. core's read_image, given an EXR file, says where to go.
#include <rtlab/core/image.hpp>

#include <filesystem>

namespace rtlab {

/// Whether the file starts with OpenEXR's magic number (false when it cannot be read).
bool is_exr_file(const std::filesystem::path& path);

/// An OpenEXR file (by its magic number, whatever its name) through read_exr, with every compression OpenEXR
/// reads (DWAA and DWAB included); any other file through read_image with `encoding`. Throws rtlab::Error naming
/// the file and the problem.
Image read_image_file(const std::filesystem::path& path, ColorEncoding encoding = ColorEncoding::srgb);

}  // namespace rtlab
