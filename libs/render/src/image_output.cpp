#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/render/exr.hpp>
#include <rtlab/render/image_output.hpp>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <string>
#include <system_error>

#include <unistd.h>

namespace rtlab {

OutputFormat output_format(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    if (ext == ".png") return OutputFormat::png;
    if (ext == ".hdr") return OutputFormat::hdr;
    if (ext == ".pfm") return OutputFormat::pfm;
    if (ext == ".exr") return OutputFormat::exr;
    throw Error(file_error_message(path, "unknown image format '" + ext + "'; known: .png, .hdr, .pfm, .exr"));
}

std::shared_ptr<const ToneOperator> make_tone_operator(const ToneRegistry& registry, std::string_view name,
                                                       Params params) {
    if (name == "none") {
        params.set_context("tone operator 'none'");
        params.check_all_used();
        return nullptr;
    }
    return registry.create(name, std::move(params));
}

namespace {

/// A name in the target's folder that no other writer in this or another process uses; it keeps the
/// target's extension so a reader of a left-over file can tell what it is.
std::filesystem::path temporary_path(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    std::filesystem::path tmp = path;
    tmp.replace_filename("." + path.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                         std::to_string(counter.fetch_add(1)) + path.extension().string());
    return tmp;
}

void write_format(const Image& image, OutputFormat format, const std::filesystem::path& path, const Image* variance) {
    switch (format) {
        case OutputFormat::png:
            return write_png(image, path);
        case OutputFormat::hdr:
            return write_hdr(image, path);
        case OutputFormat::pfm:
            return write_pfm(image, path);
        case OutputFormat::exr:
            return write_exr(image, path, variance);
    }
}

}  // namespace

void write_render_output(const Image& hdr, const std::filesystem::path& path, const ToneOperator* tone,
                         ToneReport* report, const Image* variance) {
    const OutputFormat format = output_format(path);
    if (hdr.empty()) throw Error(file_error_message(path, "cannot write an empty image"));
    if (variance && format != OutputFormat::exr)
        throw Error(file_error_message(path, "only an EXR file can carry a variance channel"));
    // Without a tone operator the PNG needs no clamped copy: write_png's encoder gives every colour the clamp
    // would change (NaN, below 0, above 1) the code of its clamped value, and the clamp leaves alpha as it is
    // (rtlab-whitted at 1280x960: a 15 MB copy less per image).
    Image display;
    if (format == OutputFormat::png && tone) display = tone->apply(hdr, report);
    const Image& out = format == OutputFormat::png && tone ? display : hdr;

    const std::filesystem::path tmp = temporary_path(path);
    try {
        write_format(out, format, tmp, variance);
        std::error_code ec;
        std::filesystem::rename(tmp, path, ec);
        if (ec) throw Error(file_error_message(path, "cannot replace it with the finished image: " + ec.message()));
    } catch (const Error& e) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        // Errors from the writers name the temporary file; the user asked for `path`.
        const std::string message = e.what();
        const std::string prefix = file_error_message(tmp, "");
        if (message.rfind(prefix, 0) != 0) throw;
        throw Error(file_error_message(path, message.substr(prefix.size())));
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw;
    }
}

}  // namespace rtlab
