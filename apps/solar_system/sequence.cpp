#include "sequence.hpp"

#include <rtlab/core/error.hpp>

#include <charconv>
#include <cstdio>

namespace rtlab::solar {

namespace {
bool parse_int(std::string_view text, int& value) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size() && !text.empty();
}
}  // namespace

FrameRange parse_frame_range(const std::string& text, int count) {
    if (text.empty()) return {0, count};
    const auto colon = text.find(':');
    FrameRange r;
    if (colon == std::string::npos || !parse_int(std::string_view(text).substr(0, colon), r.first) ||
        !parse_int(std::string_view(text).substr(colon + 1), r.last))
        throw Error("--frame-range '" + text + "': expected A:B, two frame numbers");
    if (r.first < 0 || r.first >= r.last || r.last > count)
        throw Error("--frame-range '" + text + "': needs 0 <= A < B <= " + std::to_string(count) +
                    " (--frames); frames A to B - 1 are rendered");
    return r;
}

std::filesystem::path numbered_path(const std::filesystem::path& output, int frame) {
    char number[16];
    std::snprintf(number, sizeof number, "%04d", frame);
    return output.parent_path() / (output.stem().string() + "-" + number + output.extension().string());
}

}  // namespace rtlab::solar
