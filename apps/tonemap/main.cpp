// rtlab-tonemap IN.(hdr|pfm) -o OUT.png --op ward|reinhard|exposure|aces [--key K] [--white W] [--ldmax L] [--stops S]
// Tone-maps an existing HDR image, printing the log-average luminance and the scale it used.
#include <rtlab/core/error.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include <exception>
#include <optional>

int main(int argc, char** argv) {
    CLI::App app{"rtlab-tonemap: tone-map an HDR image (Radiance .hdr or .pfm) to PNG"};
    std::string input, output, op = "reinhard";
    std::optional<double> key, white, ldmax, stops;
    app.add_option("input", input, "HDR image (.hdr or .pfm)")->required();
    app.add_option("-o,--output", output, "output image (.png; .hdr or .pfm keep linear display values)")->required();
    app.add_option("--op", op, "ward, reinhard, exposure or aces (default reinhard)");
    app.add_option("--key", key, "reinhard: key value (default 0.18)");
    app.add_option("--white", white,
                   "reinhard: white point in scaled luminance (default: image maximum; 0 = infinite)");
    app.add_option("--ldmax", ldmax, "ward: display maximum luminance in cd/m2 (default 100)");
    app.add_option("--stops", stops, "exposure, aces: exposure in stops (default 0)");
    CLI11_PARSE(app, argc, argv);
    try {
        rtlab::Params params;
        if (key) params.set("key", *key);
        if (white) params.set("white", *white);
        if (ldmax) params.set("ldmax", *ldmax);
        if (stops) params.set("stops", *stops);
        const rtlab::ToneRegistry registry = rtlab::make_tone_registry();
        const auto tone = registry.create(op, std::move(params));
        const rtlab::Image hdr = rtlab::read_image(input, rtlab::ColorEncoding::linear);
        rtlab::ToneReport report;
        const rtlab::Image display = tone->apply(hdr, &report);
        rtlab::write_image(display, output);
        fmt::print("{}: {}x{}, log-average luminance {:.6g}, max {:.6g}, scale {:.6g}\n  {}\n", input, hdr.width(),
                   hdr.height(), report.log_average, report.max_luminance, report.scale, report.summary);
        if (report.invalid_pixels > 0)
            fmt::print("  warning: {} NaN or infinite pixel(s) written black and left out of the statistics\n",
                       report.invalid_pixels);
        fmt::print("wrote {}\n", output);
    } catch (const std::exception& e) {
        fmt::print(stderr, "rtlab-tonemap: {}\n", e.what());
        return 1;
    }
    return 0;
}
