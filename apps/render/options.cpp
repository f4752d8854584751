#include "options.hpp"

#include <rtlab/render/pixel_sampler.hpp>
#include <rtlab/render/sample_buffer.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <fmt/core.h>

#include <cctype>
#include <charconv>

namespace rtlab::app {

namespace {

std::uint32_t range_number(const std::string& text, const std::string& part) {
    std::uint32_t v = 0;
    const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (part.empty() || ec != std::errc() || ptr != part.data() + part.size())
        throw UsageError("--sample-range: expected A:B with whole numbers A < B, not '" + text + "'");
    return v;
}

bool has_extension(const std::filesystem::path& path, const std::string& extension) {
    std::string e = path.extension().string();
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e == extension;
}

}  // namespace

SampleRange parse_sample_range(const std::string& text) {
    const auto colon = text.find(':');
    if (colon == std::string::npos)
        throw UsageError("--sample-range: expected A:B (samples A to B - 1 of every pixel), not '" + text + "'");
    SampleRange r{range_number(text, text.substr(0, colon)), range_number(text, text.substr(colon + 1))};
    if (r.first >= r.end) throw UsageError("--sample-range " + text + ": the end must be above the start");
    if (r.end > static_cast<std::uint32_t>(kMaxSamplesPerPixel))
        throw UsageError(fmt::format("--sample-range {}: the end must be at most {}", text, kMaxSamplesPerPixel));
    if (r.first % kDefaultBlockSamples != 0)
        throw UsageError(fmt::format(
            "--sample-range {}: the start must be a multiple of {} (the block size of the sums, so that shares "
            "merge into the bytes of one render); {} or {}",
            text, kDefaultBlockSamples, r.first / kDefaultBlockSamples * kDefaultBlockSamples,
            (r.first / kDefaultBlockSamples + 1) * kDefaultBlockSamples));
    return r;
}

std::optional<int> parse_options(int argc, char** argv, RenderOptions& o) {
    CommandLine cli("rtlab-render",
                    "rtlab-render: render a JSON scene file (docs/scene-format.md) to PNG, EXR, HDR or PFM");
    std::string scene, range, record_out;
    cli.add_positional("scene", scene, "the scene file (.json)");
    o.common.other_outputs = {".rtshare"};
    cli.add_common(o.common, make_tone_registry().names());
    cli.add_list("--plugin", o.plugins.files, "plugin module to load (FILE.so); repeatable");
    cli.add_list("--plugin-dir", o.plugins.dirs, "folder in which the plugins a scene names are found; repeatable");
    cli.add_flag("--list", o.list, "print every registered type by category with its description, and exit");
    cli.add_flag("--verbose", o.verbose, "with --list: each type's parameters too");
    cli.add_number("--noise", o.noise, 1e-6, 100.0,
                   "render until the estimated relative mean squared error (mean over pixels and R, G, B of "
                   "(I - ref)^2 / (ref^2 + 0.01)) is at most this; --spp (or the scene's spp) is then the cap per "
                   "pixel; needs --aa sobol");
    cli.add_number("--time", o.seconds, 1e-3, 1e7,
                   "render for at most this many seconds (with --noise: whichever comes first); --spp is the cap");
    cli.add_flag("--uniform", o.uniform,
                 "with --noise or --time: every pixel gets the same samples (default: adaptive sampling, more "
                 "samples where the estimate is noisy)");
    cli.add_flag("--variance", o.variance,
                 "the EXR output also holds the variance of each pixel's mean (channels variance.R, .G, .B)");
    cli.add_text("--sample-range", range,
                 "A:B: render samples A to B - 1 of every pixel into a share file (-o FILE.rtshare) for rtlab-merge; "
                 "A a multiple of 64",
                 [](const std::string& raw) { (void)parse_sample_range(raw); });
    cli.add_text("--record-rays", o.record.object,
                 "NAME: record the closest-hit and shadow queries the object of that name answers whose segment "
                 "overlaps its bounds, in its shape's own space (under its transforms: the rays its mesh's "
                 "structure receives), into --record-out's two ray files (RTRAYS01); renders on one thread",
                 [](const std::string& raw) {
                     if (raw.empty()) throw UsageError("--record-rays: give the name of one of the scene's objects");
                 });
    cli.add_text("--record-out", record_out,
                 "PREFIX: with --record-rays, write PREFIX.closest.rays and PREFIX.shadow.rays");
    cli.add_integer("--record-max", o.record.max, 1, 100000000,
                    fmt::format("with --record-rays: keep at most this many rays of each kind, count the rest "
                                "(default {})",
                                kDefaultRecordMax));
    if (const auto status = cli.parse(argc, argv)) return status;
    if (o.verbose && !o.list) return cli.usage_error("--verbose goes with --list");
    if (!o.list && scene.empty()) return cli.usage_error("give a scene file (or --list); --help shows the options");
    o.scene = scene;
    const bool share_output = has_extension(o.common.output, ".rtshare");
    if (!range.empty()) {
        o.sample_range = parse_sample_range(range);
        if (o.noise || o.seconds || o.uniform)
            return cli.usage_error(
                "--sample-range renders exactly samples A to B - 1 of every pixel: it does not go with " +
                std::string(o.noise ? "--noise" : (o.seconds ? "--time" : "--uniform")) +
                " (adaptive sampling and noise targets decide the samples themselves)");
        if (o.common.spp) return cli.usage_error("--sample-range says which samples to render: leave out --spp");
        if (o.variance)
            return cli.usage_error("--variance is for images: a share holds the sums rtlab-merge makes it from");
        if (!share_output) return cli.usage_error("--sample-range writes a share file: give -o FILE.rtshare");
    } else if (share_output) {
        return cli.usage_error("-o " + o.common.output.string() + ": a share file needs --sample-range A:B");
    }
    if (o.uniform && !o.noise && !o.seconds) return cli.usage_error("--uniform goes with --noise or --time");
    if (o.record.object.empty() && (!record_out.empty() || o.record.max))
        return cli.usage_error(std::string(record_out.empty() ? "--record-max" : "--record-out") +
                               " goes with --record-rays NAME");
    if (!o.record.object.empty()) {
        if (record_out.empty())
            return cli.usage_error("--record-rays " + o.record.object +
                                   ": give --record-out PREFIX (the files PREFIX.closest.rays and PREFIX.shadow.rays)");
        // One thread answers the queries in the same order every run: the files are reproducible.
        if (o.common.threads && *o.common.threads != 1)
            return cli.usage_error(
                "--record-rays renders on one thread, so that the ray files are the same every "
                "run: leave out --threads " +
                std::to_string(*o.common.threads));
        o.record.prefix = record_out;
    }
    if (o.variance && !o.common.output.empty() && !has_extension(o.common.output, ".exr"))
        return cli.usage_error("--variance needs EXR output (-o FILE.exr), not " + o.common.output.string());
    return std::nullopt;
}

SceneOverrides scene_overrides(const CommonOptions& o) {
    SceneOverrides overrides;
    overrides.width = o.width;
    overrides.height = o.height;
    overrides.spp = o.spp;
    overrides.aa = o.aa;
    overrides.threads = o.threads;
    overrides.tonemap = o.tonemap;
    overrides.seed = o.seed;
    overrides.max_depth = o.max_depth;
    overrides.integrator = o.integrator;
    return overrides;
}

}  // namespace rtlab::app
