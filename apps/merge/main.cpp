// rtlab-merge SHARE.rtshare... -o OUT.{png,exr,hdr,pfm} [--tonemap OP] [--variance] [--quiet]
// Adds the shares of one frame (rtlab-render --sample-range A:B) in sample order and writes the image one
// rtlab-render process would have made of all their samples: the same bytes. Shares of another seed, scene or size,
// overlapping ranges and samples no share holds are refused. docs/sample-shares.md has the file format.
// Exit status: 0 written, 1 a bad or mismatched share or a failed write, 2 bad command line.
#include <rtlab/app/command_line.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/render/sample_share.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <fmt/core.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace {

struct MergeOptions {
    std::vector<std::filesystem::path> shares;
    std::filesystem::path output;
    std::optional<std::string> tonemap;
    bool variance = false;
    bool quiet = false;
};

std::optional<int> parse_options(int argc, char** argv, MergeOptions& o) {
    rtlab::app::CommandLine cli("rtlab-merge",
                                "rtlab-merge: add the sample shares of one frame (rtlab-render --sample-range) into "
                                "the image one render would have made");
    cli.add_positionals("shares", o.shares, "the share files (.rtshare), in any order");
    std::string output;
    cli.add_text("-o,--output", output, "output image: .png (tone-mapped, sRGB), .exr, .hdr or .pfm (linear)",
                 [](const std::string& raw) { (void)rtlab::output_format(raw); });
    std::vector<std::string> tones{"none"};
    for (const auto& name : rtlab::make_tone_registry().names()) tones.push_back(name);
    cli.add_word("--tonemap", o.tonemap, tones,
                 "PNG tone operator, none clamps (default none: the shares do not hold the scene's)");
    cli.add_flag("--variance", o.variance, "the EXR output also holds the variance of each pixel's mean");
    cli.add_flag("-q,--quiet", o.quiet, "no summary");
    if (const auto status = cli.parse(argc, argv)) return status;
    if (o.shares.empty()) return cli.usage_error("give the share files to merge; --help shows the options");
    if (output.empty()) return cli.usage_error("give the output image: -o FILE");
    o.output = output;
    if (o.variance && rtlab::output_format(o.output) != rtlab::OutputFormat::exr)
        return cli.usage_error("--variance needs EXR output (-o FILE.exr), not " + o.output.string());
    return std::nullopt;
}

int run(const MergeOptions& o) {
    rtlab::app::prepare_output(o.output);
    std::shared_ptr<const rtlab::ToneOperator> tone;
    if (o.tonemap) tone = rtlab::make_tone_operator(rtlab::make_tone_registry(), *o.tonemap);
    rtlab::ShareHeader header;
    const rtlab::SampleBuffer buffer = rtlab::merge_shares(o.shares, &header);
    const rtlab::Image variance = o.variance ? buffer.mean_variance_image() : rtlab::Image();
    rtlab::write_render_output(buffer.mean_image(), o.output, tone.get(), nullptr, o.variance ? &variance : nullptr);
    if (!o.quiet)
        fmt::print("merged {} share{}: samples 0 to {} of {}x{} pixels (scene hash {:016x}, seed {}) -> {}\n",
                   o.shares.size(), o.shares.size() == 1 ? "" : "s", header.end - 1, header.width, header.height,
                   header.scene_hash, header.seed, o.output.string());
    return rtlab::app::kExitDone;
}

}  // namespace

int main(int argc, char** argv) {
    MergeOptions options;
    if (auto status = parse_options(argc, argv, options)) return *status;
    return rtlab::app::run_program("rtlab-merge", [&] { return run(options); });
}
