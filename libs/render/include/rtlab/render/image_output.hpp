#pragma once
/// \brief Writing a render: format by extension, tone mapping for PNG, never a half-written file.
#include <rtlab/core/image.hpp>
#include <rtlab/core/params.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <filesystem>
#include <memory>
#include <string_view>

namespace rtlab {

/// png: 8-bit sRGB after tone mapping; hdr (Radiance RGBE), pfm and exr (float): linear radiance.
enum class OutputFormat { png, hdr, pfm, exr };

/// The format for the path's extension (case-insensitive); throws rtlab::Error naming the path and the
/// known extensions otherwise.
OutputFormat output_format(const std::filesystem::path& path);

/// The tone operator named `name` from `registry`, built with `params`; "none" gives nullptr, which
/// write_render_output takes as clamping to [0, 1]. Unknown names and parameters throw rtlab::Error.
std::shared_ptr<const ToneOperator> make_tone_operator(const ToneRegistry& registry, std::string_view name,
                                                       Params params = {});

/// Writes `hdr` to `path` in the format of its extension: PNG through `tone` (nullptr: clamp; NaN and
/// infinite pixels are written black by either) and core's sRGB writer, the others linear. The file is
/// written under a temporary name in the same folder and renamed over `path` only once complete, so a
/// failed write leaves no file under either name and `path`, if it existed, unchanged. Throws
/// rtlab::Error naming the path and the reason. `report`, when given, receives the tone operator's report.
/// `variance` (the variance of each pixel's mean, same size) is written as EXR channels variance.R, .G, .B; any
/// other format with it is an error.
void write_render_output(const Image& hdr, const std::filesystem::path& path, const ToneOperator* tone = nullptr,
                         ToneReport* report = nullptr, const Image* variance = nullptr);

}  // namespace rtlab
