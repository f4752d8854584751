#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/render/exr.hpp>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <exception>
#include <string>

namespace rtlab {

namespace {
// RGB is three packed floats; the frame buffer slices address its members with a stride of sizeof(RGB).
static_assert(sizeof(RGB) == 3 * sizeof(float));

void insert_rgb(Imf::FrameBuffer& fb, const std::string& prefix, RGB* base, std::ptrdiff_t x0, std::ptrdiff_t y0,
                int width) {
    const std::size_t xs = sizeof(RGB), ys = sizeof(RGB) * static_cast<std::size_t>(width);
    // OpenEXR addresses pixel (x, y) of the data window as base + x * xs + y * ys.
    char* origin =
        reinterpret_cast<char*>(base) - x0 * static_cast<std::ptrdiff_t>(xs) - y0 * static_cast<std::ptrdiff_t>(ys);
    fb.insert(prefix + "R", Imf::Slice(Imf::FLOAT, origin + 0 * sizeof(float), xs, ys, 1, 1, 0.0));
    fb.insert(prefix + "G", Imf::Slice(Imf::FLOAT, origin + 1 * sizeof(float), xs, ys, 1, 1, 0.0));
    fb.insert(prefix + "B", Imf::Slice(Imf::FLOAT, origin + 2 * sizeof(float), xs, ys, 1, 1, 0.0));
}

Imf::FrameBuffer frame_buffer(RGB* base, std::ptrdiff_t x0, std::ptrdiff_t y0, int width) {
    Imf::FrameBuffer fb;
    insert_rgb(fb, "", base, x0, y0, width);
    return fb;
}
}  // namespace

void write_exr(const Image& image, const std::filesystem::path& path, const Image* variance) {
    if (image.empty()) throw Error(file_error_message(path, "cannot write an empty image"));
    if (variance && (variance->width() != image.width() || variance->height() != image.height()))
        throw Error(file_error_message(path, "the variance image's size differs from the image's"));
    try {
        Imf::Header header(image.width(), image.height());
        for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        if (variance)
            for (const char* name : {"variance.R", "variance.G", "variance.B"})
                header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(path.c_str(), header);
        // OpenEXR's frame buffer takes a non-const pointer but only reads from it when writing.
        Imf::FrameBuffer fb = frame_buffer(const_cast<RGB*>(image.pixels().data()), 0, 0, image.width());
        if (variance) insert_rgb(fb, "variance.", const_cast<RGB*>(variance->pixels().data()), 0, 0, image.width());
        file.setFrameBuffer(fb);
        file.writePixels(image.height());
    } catch (const std::exception& e) {
        throw Error(file_error_message(path, std::string("cannot write EXR: ") + e.what()));
    }
}

Image read_exr(const std::filesystem::path& path) { return read_exr_layer(path, ""); }

Image read_exr_layer(const std::filesystem::path& path, const std::string& layer) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        const long long w = static_cast<long long>(dw.max.x) - dw.min.x + 1;
        const long long h = static_cast<long long>(dw.max.y) - dw.min.y + 1;
        if (w <= 0 || h <= 0 || w * h > (1LL << 30))
            throw Error(file_error_message(path, "EXR data window of " + std::to_string(w) + "x" + std::to_string(h) +
                                                     " pixels is empty or too large"));
        Image image(static_cast<int>(w), static_cast<int>(h));
        Imf::FrameBuffer fb;
        insert_rgb(fb, layer.empty() ? "" : layer + ".", image.pixels().data(), dw.min.x, dw.min.y, image.width());
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return image;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(file_error_message(path, std::string("cannot read EXR: ") + e.what()));
    }
}

}  // namespace rtlab
