#pragma once
// rtlab-render's command line: the common flags of every rtlab app (rtlab/app/command_line.hpp) and its own.
#include <rtlab/app/command_line.hpp>
#include <rtlab/scene/scene_loader.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::app {

/// \brief The plugin modules asked for on the command line.
struct PluginOptions {
    std::vector<std::filesystem::path> files;  ///< --plugin FILE.so
    std::vector<std::filesystem::path> dirs;   ///< --plugin-dir DIR: where scenes' plugin names are found
};

/// \brief --sample-range A:B: samples A to B - 1 of every pixel.
struct SampleRange {
    std::uint32_t first = 0, end = 0;
};

/// \brief --record-rays NAME --record-out PREFIX [--record-max N]: the rays one object answers, in its shape's own
/// space, into PREFIX.closest.rays and PREFIX.shadow.rays (rtlab/render/ray_recorder.hpp).
struct RecordOptions {
    std::string object;  ///< empty: no recording
    std::filesystem::path prefix;
    std::optional<int> max;  ///< rays kept of each kind (default kDefaultRecordMax)
};

/// --record-max's default: 128 MB of rays of each kind at most.
inline constexpr int kDefaultRecordMax = 4000000;

struct RenderOptions {
    std::filesystem::path scene;
    CommonOptions common;  ///< common.output empty: the scene's render.output
    PluginOptions plugins;
    bool list = false;
    bool verbose = false;                     ///< with --list: every type's parameters too
    std::optional<double> noise;              ///< --noise E: render until the estimated relMSE is at most E
    std::optional<double> seconds;            ///< --time S: render for at most S seconds
    bool uniform = false;                     ///< --uniform: no adaptive sampling with --noise or --time
    bool variance = false;                    ///< --variance: the EXR output carries the variance of each pixel's mean
    std::optional<SampleRange> sample_range;  ///< --sample-range A:B: write a share file (.rtshare)
    RecordOptions record;
};

/// Parses the command line. Returns the exit status when the program should stop now (--help, a usage
/// error: 0 or 2), nothing when it should go on.
std::optional<int> parse_options(int argc, char** argv, RenderOptions& options);

/// What the loader takes from the command line: size, sampling, threads, tone operator, seed.
SceneOverrides scene_overrides(const CommonOptions& options);

/// Parses "A:B" (whole numbers, A < B <= kMaxSamplesPerPixel, A a multiple of kDefaultBlockSamples); throws
/// UsageError naming --sample-range otherwise.
SampleRange parse_sample_range(const std::string& text);

}  // namespace rtlab::app
