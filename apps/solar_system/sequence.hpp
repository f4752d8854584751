#pragma once
/// \brief The frames of an rtlab-solar-system sequence: --frame-range parsing and numbered file names.
#include <filesystem>
#include <string>

namespace rtlab::solar {

/// \brief Frames first .. last - 1 of a sequence of `count`.
struct FrameRange {
    int first = 0, last = 1;
};

/// "A:B" with 0 <= A < B <= count: frames A to B - 1 (half-open, so that 0:50 and 50:100 split 100 frames
/// between two processes). An empty text gives the whole sequence. Throws rtlab::Error saying what is wrong.
FrameRange parse_frame_range(const std::string& text, int count);

/// out/solar.png, frame 7 -> out/solar-0007.png: the stem, a dash, the frame number in four digits (more when
/// needed), the extension.
std::filesystem::path numbered_path(const std::filesystem::path& output, int frame);

}  // namespace rtlab::solar
