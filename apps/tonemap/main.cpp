// rtlab-tonemap IN.(hdr|pfm|exr) -o OUT.png --op ward|reinhard|exposure|aces [--key K] [--white W] [--ldmax L] [--stops
// S] Tone-maps an existing HDR image, printing the log-average luminance and the scale it used. Exit status: 0 written,
// 1 bad image or failed write, 2 bad command line.
#include <rtlab/app/command_line.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/render/image_input.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <fmt/core.h>

#include <optional>

int main(int argc, char** argv) {
    rtlab::app::CommandLine cli("rtlab-tonemap",
                                "rtlab-tonemap: tone-map an HDR image (Radiance .hdr, .pfm or OpenEXR .exr) to PNG");
    const rtlab::ToneRegistry registry = rtlab::make_tone_registry();
    std::string input, output, op = "reinhard";
    std::optional<double> key, white, ldmax, stops;
    cli.add_positional("input", input, "HDR image (.hdr, .pfm or .exr)");
    cli.add_text("-o,--output", output, "output image (.png; .hdr or .pfm keep linear display values)");
    cli.add_word("--op", op, registry.names(), "tone operator");
    cli.add_number("--key", key, 1e-6, 1e6, "reinhard: key value (default 0.18)");
    cli.add_number("--white", white, 0.0, 1e30,
                   "reinhard: white point in scaled luminance (default: image maximum; 0 = infinite)");
    cli.add_number("--ldmax", ldmax, 1e-6, 1e9, "ward: display maximum luminance in cd/m2 (default 100)");
    cli.add_number("--stops", stops, -64.0, 64.0, "exposure, aces: exposure in stops (default 0)");
    if (const auto status = cli.parse(argc, argv)) return *status;
    if (input.empty()) return cli.usage_error("give an HDR image (.hdr, .pfm or .exr); --help shows the options");
    if (output.empty()) return cli.usage_error("give -o OUT.png");
    return rtlab::app::run_program(cli.program(), [&] {
        rtlab::Params params;
        if (key) params.set("key", *key);
        if (white) params.set("white", *white);
        if (ldmax) params.set("ldmax", *ldmax);
        if (stops) params.set("stops", *stops);
        std::shared_ptr<const rtlab::ToneOperator> tone;
        try {
            tone = registry.create(op, std::move(params));
        } catch (const rtlab::Error& e) {
            // Its parameters all come from the command line ("--key" for "stops", say).
            throw rtlab::app::UsageError(e.what());
        }
        const rtlab::Image hdr = rtlab::read_image_file(input, rtlab::ColorEncoding::linear);
        rtlab::ToneReport report;
        const rtlab::Image display = tone->apply(hdr, &report);
        rtlab::app::prepare_output(output);
        rtlab::write_image(display, output);
        fmt::print("{}: {}x{}, log-average luminance {:.6g}, max {:.6g}, scale {:.6g}\n  {}\n", input, hdr.width(),
                   hdr.height(), report.log_average, report.max_luminance, report.scale, report.summary);
        if (report.invalid_pixels > 0)
            fmt::print("  warning: {} NaN or infinite pixel(s) written black and left out of the statistics\n",
                       report.invalid_pixels);
        fmt::print("wrote {}\n", output);
        return rtlab::app::kExitDone;
    });
}
