#pragma once
// Running an app executable from a test: exit status and what it wrote on stderr; and image measures.
#include <rtlab/core/image.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace rtlab::test {

struct AppRun {
    int status = -1;  // the exit status, -1 when it did not exit normally
    std::string err;
    std::string out;
};

inline std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Runs `exe args` (a shell command line) with `environment` ("NAME=value ...", through env) added.
inline AppRun run_app(const std::string& exe, const std::string& args, const std::filesystem::path& scratch,
                      const std::string& environment = "") {
    const auto err_file = scratch / "stderr.txt", out_file = scratch / "stdout.txt";
    const std::string command = (environment.empty() ? "" : "env " + environment + " ") + "'" + exe + "' " + args +
                                " > '" + out_file.string() + "' 2> '" + err_file.string() + "'";
    const int raw = std::system(command.c_str());
    AppRun run;
    if (raw != -1 && WIFEXITED(raw)) run.status = WEXITSTATUS(raw);
    run.err = read_text(err_file);
    run.out = read_text(out_file);
    return run;
}

inline bool same_pixels(const Image& a, const Image& b) {
    if (a.width() != b.width() || a.height() != b.height()) return false;
    for (std::size_t i = 0; i < a.pixel_count(); ++i)
        if (a.pixels()[i] != b.pixels()[i]) return false;
    return true;
}

/// Mean of the pixels in [x0, x1) x [y0, y1).
inline RGB mean(const Image& image, int x0, int y0, int x1, int y1) {
    RGB sum;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += image.at(x, y);
    return sum / static_cast<float>((x1 - x0) * (y1 - y0));
}

}  // namespace rtlab::test
