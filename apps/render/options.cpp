#include "options.hpp"

#include <CLI/CLI.hpp>

namespace rtlab::app {

std::optional<int> parse_options(int argc, char** argv, RenderOptions& o) {
    CLI::App app{"rtlab-render: render a JSON scene file (docs/scene-format.md) to PNG, EXR, HDR or PFM"};
    std::string scene, output;
    std::vector<std::string> data_dirs, plugin_files, plugin_dirs;
    int width = 0, height = 0, spp = 0, threads = -1;
    std::string aa, tonemap;
    std::uint64_t seed = 0;
    app.add_option("scene", scene, "the scene file (.json)");
    app.add_option("-o,--output", output,
                   "output image: .png (tone-mapped, sRGB), .exr, .hdr or .pfm (linear); "
                   "default: the scene's render.output");
    auto* w = app.add_option("--width", width, "image width in pixels (alone: keeps the scene's aspect ratio)");
    auto* h = app.add_option("--height", height, "image height in pixels (alone: keeps the scene's aspect ratio)");
    auto* s = app.add_option("--spp", spp, "samples per pixel for grid, random and jittered");
    auto* a = app.add_option("--aa", aa, "anti-aliasing: none, grid, random, jittered or adaptive");
    auto* t = app.add_option("--threads", threads, "worker threads (0: all cores); the image does not depend on it");
    auto* tm = app.add_option("--tonemap", tonemap,
                              "tone operator for PNG output: none (clamp) or a registered one "
                              "(--list)");
    auto* sd = app.add_option("--seed", seed, "seed of every sample");
    app.add_option("--data-dir", data_dirs,
                   "folder searched for the files a scene names (after the scene's folder, "
                   "before RTLAB_DATA_PATH); repeatable");
    app.add_option("--plugin", plugin_files, "plugin module to load (FILE.so); repeatable");
    app.add_option("--plugin-dir", plugin_dirs, "folder in which the plugins a scene names are found; repeatable");
    app.add_flag("-q,--quiet", o.quiet, "no progress bar and no statistics");
    app.add_flag("--list", o.list, "print every registered type by category with its description, and exit");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int status = app.exit(e);
        return status == 0 ? 0 : 2;
    }
    if (!o.list && scene.empty()) {
        std::fputs("rtlab-render: give a scene file (or --list); --help shows the options\n", stderr);
        return 2;
    }
    o.scene = scene;
    o.output = output;
    if (*w) o.overrides.width = width;
    if (*h) o.overrides.height = height;
    if (*s) o.overrides.spp = spp;
    if (*a) o.overrides.aa = aa;
    if (*t) o.overrides.threads = threads;
    if (*tm) o.overrides.tonemap = tonemap;
    if (*sd) o.overrides.seed = seed;
    for (auto& d : data_dirs) o.data_dirs.emplace_back(d);
    for (auto& f : plugin_files) o.plugins.files.emplace_back(f);
    for (auto& d : plugin_dirs) o.plugins.dirs.emplace_back(d);
    return std::nullopt;
}

}  // namespace rtlab::app
