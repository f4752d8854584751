#include "truncation_check.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace rtlab::detail {

namespace {

[[noreturn]] void truncated(const std::filesystem::path& path, const std::string& what, std::size_t size) {
    throw Error(
        file_error_message(path, "truncated " + what + " (the file ends after " + std::to_string(size) + " bytes)"));
}

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

// A PNG is the signature and chunks of length (4 bytes, big-endian), type (4), data and CRC (4), up to IEND.
// Every chunk must be whole, IEND's CRC included: stb would accept a file cut inside the CRCs it never
// checks, but a file cut anywhere has lost bytes, and saying so is the honest answer.
void check_png(const std::vector<unsigned char>& bytes, const std::filesystem::path& path) {
    std::size_t pos = sizeof kPngSignature;
    for (int chunk = 1;; ++chunk) {
        if (bytes.size() - pos < 8) {
            truncated(path,
                      "PNG: chunk " + std::to_string(chunk) + " at byte " + std::to_string(pos) +
                          " has no complete header, and no IEND chunk came before it",
                      bytes.size());
        }
        const std::uint64_t length = (std::uint64_t{bytes[pos]} << 24) | (std::uint64_t{bytes[pos + 1]} << 16) |
                                     (std::uint64_t{bytes[pos + 2]} << 8) | std::uint64_t{bytes[pos + 3]};
        const std::string type(reinterpret_cast<const char*>(bytes.data() + pos + 4), 4);
        const std::uint64_t needed = 12 + length;
        if (bytes.size() - pos < needed)
            truncated(path,
                      "PNG: chunk '" + type + "' at byte " + std::to_string(pos) + " needs " + std::to_string(needed) +
                          " bytes, " + std::to_string(bytes.size() - pos) + " are left",
                      bytes.size());
        pos += needed;
        if (type == "IEND") return;
    }
}

// Mirrors stb's reader: a header line is everything up to '\n'.
std::string_view next_line(const std::vector<unsigned char>& bytes, std::size_t& pos) {
    const auto* text = reinterpret_cast<const char*>(bytes.data());
    const std::size_t start = pos;
    while (pos < bytes.size() && text[pos] != '\n') ++pos;
    const std::string_view line(text + start, pos - start);
    if (pos < bytes.size()) ++pos;
    return line;
}

// "-Y height +X width", the only layout stb reads; false when the line is not that.
bool parse_resolution(std::string_view line, std::int64_t& width, std::int64_t& height) {
    auto number = [&](std::string_view prefix, std::int64_t& value) {
        if (line.substr(0, prefix.size()) != prefix) return false;
        line.remove_prefix(prefix.size());
        std::size_t digits = 0;
        value = 0;
        while (digits < line.size() && digits < 10 && line[digits] >= '0' && line[digits] <= '9')
            value = 10 * value + (line[digits++] - '0');
        line.remove_prefix(digits);
        while (!line.empty() && line.front() == ' ') line.remove_prefix(1);
        return digits > 0;
    };
    return number("-Y ", height) && number("+X ", width) && width > 0 && height > 0;
}

// A Radiance HDR raster: flat RGBE pixels when the width is below 8 or at least 32768, otherwise per scanline
// either a run-length record (2, 2, width as two bytes, then four channels of runs and literal dumps) or, the
// first time a scanline does not start that way, flat pixels for the whole image from there on, as stb
// reads it.
void check_hdr(const std::vector<unsigned char>& bytes, const std::filesystem::path& path) {
    std::size_t pos = 0;
    next_line(bytes, pos);  // #?RADIANCE or #?RGBE, which stb has recognised
    while (pos < bytes.size() && !next_line(bytes, pos).empty()) {
    }
    if (pos >= bytes.size()) truncated(path, "Radiance HDR: the header has no resolution line", bytes.size());
    std::int64_t width = 0, height = 0;
    if (!parse_resolution(next_line(bytes, pos), width, height)) return;  // stb names what is wrong
    const std::size_t size = bytes.size();
    auto scanline_cut = [&](std::int64_t row) {
        truncated(path,
                  "Radiance HDR: scanline " + std::to_string(row + 1) + " of " + std::to_string(height) + " is cut off",
                  size);
    };
    auto check_flat = [&](std::int64_t pixels, std::int64_t row) {
        const std::uint64_t needed = 4 * static_cast<std::uint64_t>(pixels);
        if (size - pos < needed) scanline_cut(row + static_cast<std::int64_t>((size - pos) / 4 / width));
    };
    if (width < 8 || width >= 32768) return check_flat(width * height, 0);
    for (std::int64_t row = 0; row < height; ++row) {
        if (size - pos < 4) scanline_cut(row);
        const unsigned char* record = bytes.data() + pos;
        pos += 4;
        if (record[0] != 2 || record[1] != 2 || (record[2] & 0x80)) {
            // stb takes these four bytes as the first pixel and reads every pixel of the image flat after it.
            return check_flat(width * height - 1, 0);
        }
        if (((record[2] << 8) | record[3]) != width) return;  // stb reports the bad scanline length
        for (int channel = 0; channel < 4; ++channel) {
            for (std::int64_t filled = 0; filled < width;) {
                if (pos >= size) scanline_cut(row);
                const unsigned count = bytes[pos++];
                if (count > 128) {  // a run of count - 128 copies of the next byte
                    if (pos >= size) scanline_cut(row);
                    ++pos;
                    filled += count - 128;
                } else {  // count literal bytes
                    if (size - pos < count) scanline_cut(row);
                    pos += count;
                    filled += count;
                }
                if (filled > width) return;  // stb reports the bad run
            }
        }
    }
}

bool starts_with(const std::vector<unsigned char>& bytes, std::string_view prefix) {
    return bytes.size() >= prefix.size() && std::memcmp(bytes.data(), prefix.data(), prefix.size()) == 0;
}

}  // namespace

void check_not_truncated(const std::vector<unsigned char>& bytes, const std::filesystem::path& path) {
    if (bytes.size() >= sizeof kPngSignature && std::memcmp(bytes.data(), kPngSignature, sizeof kPngSignature) == 0)
        check_png(bytes, path);
    else if (starts_with(bytes, "#?RADIANCE\n") || starts_with(bytes, "#?RGBE\n"))
        check_hdr(bytes, path);
}

}  // namespace rtlab::detail
