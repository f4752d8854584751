// Image files cut short anywhere give an rtlab::Error naming the file: stb reads past the end of a PNG or
// Radiance HDR buffer as zeros (and never stops inside a run-length HDR scanline), so rtlab checks first.
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/core/image.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"

#include <cstring>
#include <string>
#include <vector>

using namespace rtlab;
using Catch::Matchers::Contains;

namespace {

const auto dir = test::scratch_dir("core_image_truncation");

// Smooth rows (literal dumps in a run-length HDR) over flat rows (runs), with values far above 1.
Image test_image(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.at(x, y) = y < h / 2 ? RGB(0.9f * x / w, 0.3f + 0.5f * y / h, 0.2f + 0.05f * (x % 7))
                                     : RGB(3.0f, 0.25f, 40.0f * (y % 3));
    return img;
}

// Where a header of `lines` lines ends, counting from `from`: the byte after the last of them.
std::size_t after_lines(const std::vector<unsigned char>& bytes, int lines, std::size_t from = 0) {
    std::size_t pos = from;
    for (int seen = 0; pos < bytes.size() && seen < lines; ++pos) seen += bytes[pos] == '\n';
    return pos;
}

// A Radiance header runs to a blank line, then comes the resolution line.
std::size_t hdr_header_size(const std::vector<unsigned char>& bytes) {
    const std::string text(bytes.begin(), bytes.end());
    const std::size_t blank = text.find("\n\n");
    return blank == std::string::npos ? bytes.size() : after_lines(bytes, 3, blank);
}

struct Cuts {
    int tried = 0, errors = 0, named = 0, said_truncated = 0;
    std::string first_message;
};

// Every length from 1 byte to one short of the whole file; from `raster` on the message must say "truncated".
Cuts cut_everywhere(const std::vector<unsigned char>& whole, const std::string& name, std::size_t raster) {
    Cuts c;
    for (std::size_t size = 1; size < whole.size(); ++size) {
        const auto path = dir / name;
        write_binary_file(path, std::vector<unsigned char>(whole.begin(), whole.begin() + size));
        ++c.tried;
        try {
            (void)read_image(path);
        } catch (const Error& e) {
            const std::string message = e.what();
            ++c.errors;
            c.named += message.find(name) != std::string::npos;
            if (size >= raster) c.said_truncated += message.find("truncated") != std::string::npos;
            if (size == raster) c.first_message = message;
        }
    }
    return c;
}

}  // namespace

TEST_CASE("a Radiance HDR file cut anywhere is an error saying it is truncated", "[image]") {
    // Width 16 is written run-length encoded, width 5 flat (stb's writer and reader both switch below 8).
    for (int width : {16, 5}) {
        const std::string name = "cut" + std::to_string(width) + ".hdr";
        write_hdr(test_image(width, 12), dir / "whole.hdr");
        const std::vector<unsigned char> whole = read_binary_file(dir / "whole.hdr");
        REQUIRE(read_image(dir / "whole.hdr").width() == width);  // the uncut file reads
        const std::size_t raster = hdr_header_size(whole);
        REQUIRE(raster < whole.size());
        const Cuts c = cut_everywhere(whole, name, raster);
        INFO(name << ": " << whole.size() << " bytes, raster from byte " << raster << "; " << c.first_message);
        CHECK(c.errors == c.tried);
        CHECK(c.named == c.tried);
        CHECK(c.said_truncated == static_cast<int>(whole.size() - raster));
    }
    // Header only, the way the stability tests write it.
    write_binary_file(dir / "header_only.hdr", [] {
        const std::string s = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16 +X 16\n";
        return std::vector<unsigned char>(s.begin(), s.end());
    }());
    CHECK_THROWS_WITH(read_image(dir / "header_only.hdr"),
                      Contains("header_only.hdr") && Contains("truncated") && Contains("scanline 1 of 16"));
}

TEST_CASE("a run-length HDR scanline whose runs overflow the width is still a decode error", "[image]") {
    // A run of 17 copies in a 16 wide scanline: whole, not truncated, but corrupt; stb names it.
    std::string s = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 16\n";
    s += std::string("\x02\x02\x00\x10", 4) + std::string("\x91\x01", 2) + std::string(64, '\x01');
    write_binary_file(dir / "overrun.hdr", std::vector<unsigned char>(s.begin(), s.end()));
    CHECK_THROWS_WITH(read_image(dir / "overrun.hdr"), Contains("overrun.hdr") && Contains("cannot decode"));
}

TEST_CASE("a PNG file cut anywhere is an error naming the file", "[image]") {
    write_png(test_image(16, 12), dir / "whole.png");
    const std::vector<unsigned char> whole = read_binary_file(dir / "whole.png");
    REQUIRE(read_image(dir / "whole.png").width() == 16);
    const std::size_t raster = 8;  // after the signature, every cut loses part of a chunk
    const Cuts c = cut_everywhere(whole, "cut.png", raster);
    INFO(whole.size() << " bytes; " << c.first_message);
    CHECK(c.errors == c.tried);
    CHECK(c.named == c.tried);
    CHECK(c.said_truncated == static_cast<int>(whole.size() - raster));
}

TEST_CASE("a PFM file cut anywhere is an error naming the file", "[image]") {
    write_pfm(test_image(6, 5), dir / "whole.pfm");
    const std::vector<unsigned char> whole = read_binary_file(dir / "whole.pfm");
    REQUIRE(read_image(dir / "whole.pfm").width() == 6);
    const std::size_t raster = after_lines(whole, 3);  // PF, size, scale
    const Cuts c = cut_everywhere(whole, "cut.pfm", raster);
    INFO(whole.size() << " bytes, raster from byte " << raster << "; " << c.first_message);
    CHECK(c.errors == c.tried);
    CHECK(c.named == c.tried);
    CHECK(c.said_truncated == static_cast<int>(whole.size() - raster));
}
