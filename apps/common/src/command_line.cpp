#include <rtlab/app/command_line.hpp>
#include <rtlab/app/process_heap.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/core/spelling.hpp>
#include <rtlab/render/image_limits.hpp>
#include <rtlab/render/image_output.hpp>
#include <rtlab/render/pixel_sampler.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <system_error>

namespace rtlab::app {

namespace fs = std::filesystem;

namespace {

std::string join(const std::vector<std::string>& words, const char* separator = ", ") {
    std::string out;
    for (const auto& w : words) out += (out.empty() ? "" : separator) + w;
    return out;
}

// The name messages show for "-o,--output": the first one.
std::string display_name(const std::string& flags) { return flags.substr(0, flags.find(',')); }

std::optional<std::int64_t> parse_whole(const std::string& raw) {
    std::int64_t value = 0;
    const char* end = raw.data() + raw.size();
    const char* first = raw.data() + (raw.starts_with('+') ? 1 : 0);
    const auto [ptr, ec] = std::from_chars(first, end, value);
    if (ptr != end || raw.empty()) return std::nullopt;
    if (ec == std::errc::result_out_of_range)
        return raw.starts_with('-') ? std::numeric_limits<std::int64_t>::min()
                                    : std::numeric_limits<std::int64_t>::max();
    if (ec != std::errc()) return std::nullopt;
    return value;
}

std::int64_t whole_number(const std::string& name, const std::string& raw) {
    if (const auto v = parse_whole(raw)) return *v;
    throw UsageError(name + ": expected a whole number, not '" + raw + "'");
}

double real_number(const std::string& name, const std::string& raw) {
    char* end = nullptr;
    const double v = raw.empty() ? 0.0 : std::strtod(raw.c_str(), &end);
    if (raw.empty() || end != raw.c_str() + raw.size() || !std::isfinite(v))
        throw UsageError(name + ": expected a number, not '" + raw + "'");
    return v;
}

std::string checked_word(const std::string& name, const std::string& raw, const std::vector<std::string>& words) {
    for (const auto& w : words)
        if (w == raw) return raw;
    throw UsageError(name + ": '" + raw + "' is not one of " + join(words) + did_you_mean(raw, words));
}

// An image side: the same limit as a scene file's.
int image_side(const std::string& name, const std::string& raw) {
    const std::int64_t v = whole_number(name, raw);
    if (v < 1) throw UsageError(name + ": must be at least 1, not " + raw);
    if (v > kMaxImageSide) throw UsageError(fmt::format("{}: must be at most {}, not {}", name, kMaxImageSide, raw));
    return static_cast<int>(v);
}

bool is_square(int n) {
    const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
    return side * side == n;
}

// The squares on either side of n: "9 or 16".
std::string nearest_squares(int n) {
    const int below = static_cast<int>(std::sqrt(static_cast<double>(n)));
    if (below < 1) return "1";
    return fmt::format("{} or {}", below * below, (below + 1) * (below + 1));
}

// "-5", "-0.5": values, not flags.
bool looks_like_number(const std::string& arg) {
    return arg.size() > 1 && arg[0] == '-' && (std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.');
}

}  // namespace

CommandLine::CommandLine(std::string program, const std::string& description)
    : m_program(std::move(program)), m_app(description, m_program) {
    // Unknown flags and stray arguments are reported by check_extras, with a suggestion and the program's name.
    m_app.allow_extras();
}

void CommandLine::add_checked(const std::string& flags, const std::string& type, const std::string& help,
                              std::function<void(const std::string&, const std::string&)> apply) {
    std::string& raw = m_raw.emplace_back();
    CLI::Option* option =
        m_app.add_option(flags, raw, help)->type_name(type)->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    m_checks.push_back({option, display_name(flags), &raw, std::move(apply)});
}

void CommandLine::add_integer(const std::string& flags, std::optional<int>& target, int lo, int hi,
                              const std::string& help) {
    add_checked(flags, "INT", help, [&target, lo, hi](const std::string& name, const std::string& raw) {
        const std::int64_t v = whole_number(name, raw);
        if (v < lo || v > hi) throw UsageError(fmt::format("{}: must be in [{}, {}], not {}", name, lo, hi, raw));
        target = static_cast<int>(v);
    });
}

void CommandLine::add_number(const std::string& flags, std::optional<double>& target, double lo, double hi,
                             const std::string& help) {
    add_checked(flags, "NUMBER", help, [&target, lo, hi](const std::string& name, const std::string& raw) {
        const double v = real_number(name, raw);
        if (v < lo || v > hi) throw UsageError(fmt::format("{}: must be in [{}, {}], not {}", name, lo, hi, raw));
        target = v;
    });
}

void CommandLine::add_number(const std::string& flags, std::optional<float>& target, double lo, double hi,
                             const std::string& help) {
    add_checked(flags, "NUMBER", help, [&target, lo, hi](const std::string& name, const std::string& raw) {
        const double v = real_number(name, raw);
        if (v < lo || v > hi) throw UsageError(fmt::format("{}: must be in [{}, {}], not {}", name, lo, hi, raw));
        target = static_cast<float>(v);
    });
}

void CommandLine::add_word(const std::string& flags, std::optional<std::string>& target, std::vector<std::string> words,
                           const std::string& help) {
    const std::string text = help + " (" + join(words) + ")";
    add_checked(flags, "WORD", text,
                [&target, words = std::move(words)](const std::string& name, const std::string& raw) {
                    target = checked_word(name, raw, words);
                });
}

void CommandLine::add_word(const std::string& flags, std::string& target, std::vector<std::string> words,
                           const std::string& help) {
    const std::string text = help + " (" + join(words) + "; default " + target + ")";
    add_checked(flags, "WORD", text,
                [&target, words = std::move(words)](const std::string& name, const std::string& raw) {
                    target = checked_word(name, raw, words);
                });
}

void CommandLine::add_text(const std::string& flags, std::string& target, const std::string& help,
                           std::function<void(const std::string&)> check) {
    add_checked(flags, "TEXT", help,
                [&target, check = std::move(check)](const std::string& name, const std::string& raw) {
                    if (raw.empty()) throw UsageError(name + ": expected a value, not an empty one");
                    if (check) {
                        try {
                            check(raw);
                        } catch (const UsageError&) {
                            throw;
                        } catch (const Error& e) {
                            throw UsageError(name + ": " + e.what());
                        }
                    }
                    target = raw;
                });
}

void CommandLine::add_list(const std::string& flags, std::vector<fs::path>& target, const std::string& help) {
    // One value per occurrence: CLI11's vector options otherwise take every argument up to the next flag,
    // the scene file included ("--plugin x.so scene.json" left no scene).
    m_app
        .add_option_function<std::vector<std::string>>(
            flags, [&target](const std::vector<std::string>& values) { target.assign(values.begin(), values.end()); },
            help)
        ->type_name("PATH")
        ->expected(1)
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

void CommandLine::add_flag(const std::string& flags, bool& target, const std::string& help) {
    m_app.add_flag(flags, target, help);
}

void CommandLine::add_positional(const std::string& name, std::string& target, const std::string& help) {
    m_app.add_option(name, target, help)->expected(1);
}

void CommandLine::add_positionals(const std::string& name, std::vector<fs::path>& target, const std::string& help) {
    m_app
        .add_option_function<std::vector<std::string>>(
            name, [&target](const std::vector<std::string>& values) { target.assign(values.begin(), values.end()); },
            help)
        ->expected(0, std::numeric_limits<int>::max());
}

void CommandLine::add_common(CommonOptions& o, const std::vector<std::string>& tone_operators) {
    std::string& output = m_raw.emplace_back(o.output.string());  // the text; the check sets o.output
    std::string others;
    for (const auto& e : o.other_outputs) others += ", " + e;
    add_text(
        "-o,--output", output,
        "output image: .png (tone-mapped, sRGB), .exr, .hdr or .pfm (linear)" + others +
            (o.output.empty() ? std::string("; default: the scene's render.output") : "; default " + o.output.string()),
        [&o](const std::string& raw) {
            const std::string extension = fs::path(raw).extension().string();
            const bool other =
                std::find(o.other_outputs.begin(), o.other_outputs.end(), extension) != o.other_outputs.end();
            if (!other) (void)output_format(raw);  // an unknown extension fails now, not after the render
            o.output = raw;
        });
    const std::optional<int> default_width = o.width, default_height = o.height;
    const std::string keeps = default_width ? fmt::format("; default {}x{}", *default_width, *default_height)
                                            : std::string("; default: the scene's");
    add_checked("--width", "INT", "image width in pixels (alone: keeps the aspect ratio" + keeps + ")",
                [&o](const std::string& name, const std::string& raw) { o.width = image_side(name, raw); });
    add_checked("--height", "INT", "image height in pixels (alone: keeps the aspect ratio)",
                [&o](const std::string& name, const std::string& raw) { o.height = image_side(name, raw); });
    add_word("--aa", o.aa, {"none", "grid", "random", "jittered", "sobol", "adaptive"},
             "anti-aliasing (default: the scene's); sobol: progressive Owen-scrambled Sobol samples");
    add_integer("--spp", o.spp, 1, kMaxSamplesPerPixel,
                "exactly this many samples per pixel in the pattern of --aa or the scene: any number for random, a "
                "square for grid and jittered");
    add_number("--aa-threshold", o.aa_threshold, 0.0, 3.0,
               "adaptive: colour difference that splits a square (default: the scene's)");
    add_integer("--aa-depth", o.aa_depth, 0, kMaxAdaptiveDepth, "adaptive: subdivision depth (default: the scene's)");
    add_integer("--depth", o.max_depth, 0, 64,
                "reflection and refraction depth; direct and path: bounces, 1 = direct light (default: the scene's)");
    add_word("--integrator", o.integrator, {"whitted", "direct", "path", "photon", "sppm"},
             "whitted (the course's recursion), direct (light and BSDF sampling, one bounce), path (a path "
             "tracer), photon (photon mapping) or sppm (stochastic progressive photon mapping; --spp counts its "
             "iterations) (default: the scene's)");
    add_integer("--threads", o.threads, 0, 1024, "render threads (0: every core); the image does not depend on it");
    add_checked("--seed", "INT", "seed of every random sample (the image is the same for the same seed)",
                [&o](const std::string& name, const std::string& raw) {
                    std::uint64_t v = 0;
                    const auto [ptr, ec] = std::from_chars(raw.data(), raw.data() + raw.size(), v);
                    if (raw.empty() || ec != std::errc() || ptr != raw.data() + raw.size())
                        throw UsageError(name + ": expected a whole number in [0, 2^64 - 1], not '" + raw + "'");
                    o.seed = v;
                });
    std::vector<std::string> tones{"none"};
    tones.insert(tones.end(), tone_operators.begin(), tone_operators.end());
    add_word("--tonemap", o.tonemap, std::move(tones), "PNG tone operator, none clamps (default: the scene's)");
    add_flag("-q,--quiet", o.quiet, "no progress bar and no summary");
    add_flag("--no-packets", o.no_packets,
             "trace camera rays one at a time instead of in coherent groups (for measurements; the same image)");
    add_list("--data-dir", o.data_dirs, "folder searched first for the data files (repeatable)");

    const CLI::Option* width_flag = m_app.get_option("--width");
    const CLI::Option* height_flag = m_app.get_option("--height");
    m_after.push_back([&o, default_width, default_height, width_flag, height_flag] {
        // One side alone keeps the default's aspect ratio; both together must fit the pixel limit.
        const bool width_given = width_flag->count() > 0, height_given = height_flag->count() > 0;
        if (default_width && default_height && width_given != height_given) {
            if (width_given)
                o.height =
                    std::max(1, static_cast<int>(std::lround(double(*default_height) * *o.width / *default_width)));
            else
                o.width =
                    std::max(1, static_cast<int>(std::lround(double(*default_width) * *o.height / *default_height)));
        }
        if (o.width && o.height && std::max(*o.width, *o.height) > kMaxImageSide)
            throw UsageError(fmt::format("--width/--height: {}x{} (the default's aspect ratio) is more than {} a side",
                                         *o.width, *o.height, kMaxImageSide));
        if (o.width && o.height && std::int64_t{*o.width} * *o.height > kMaxImagePixels)
            throw UsageError(
                fmt::format("--width/--height: {}x{} is more than {} pixels", *o.width, *o.height, kMaxImagePixels));
        // What can be checked of --aa and --spp without the scene (a scene's spp is unknown here: 1 passes).
        if (o.aa) {
            RenderSettings s;
            s.pattern = parse_pixel_pattern(*o.aa);
            s.spp = o.spp.value_or(1);
            check_sampling(s, o);
        }
    });
}

std::vector<std::string> CommandLine::flag_names() const {
    std::vector<std::string> names;
    for (const CLI::Option* option : m_app.get_options()) {
        for (const auto& n : option->get_lnames()) names.push_back("--" + n);
        for (const auto& n : option->get_snames()) names.push_back("-" + n);
    }
    return names;
}

std::optional<std::string> CommandLine::flag_without_value(int argc, const char* const* argv) const {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const CLI::Option* option = arg.starts_with('-') ? m_app.get_option_no_throw(arg) : nullptr;
        if (!option || option->get_expected_min() < 1) continue;
        const bool has_value =
            i + 1 < argc && (!std::string_view(argv[i + 1]).starts_with('-') || looks_like_number(argv[i + 1]));
        if (!has_value) return arg;
    }
    return std::nullopt;
}

void CommandLine::check_extras() const {
    const std::vector<std::string> extras = m_app.remaining();
    for (const auto& arg : extras) {
        if (!arg.starts_with('-') || arg == "-" || looks_like_number(arg)) continue;
        const std::string flag = arg.substr(0, arg.find('='));
        throw UsageError("unknown option '" + flag + "'" + did_you_mean(flag, flag_names()));
    }
    if (!extras.empty()) throw UsageError("unexpected argument '" + extras.front() + "'");
}

std::optional<int> CommandLine::parse(int argc, const char* const* argv) {
    try {
        m_app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return m_app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return m_app.exit(e);
    } catch (const CLI::ParseError& e) {
        // CLI11's message for a flag without its value is "--width: 1 required TEXT missing"; an unknown flag can
        // make it fail on what follows: report the flag.
        if (const auto flag = flag_without_value(argc, argv)) return usage_error(*flag + ": needs a value");
        try {
            check_extras();
        } catch (const UsageError& u) {
            return usage_error(u.what());
        }
        return usage_error(e.what());
    }
    try {
        if (const auto flag = flag_without_value(argc, argv)) throw UsageError(*flag + ": needs a value");
        check_extras();
        for (const Check& c : m_checks)
            if (c.option->count() > 0) c.apply(c.name, *c.raw);
        for (const auto& after : m_after) after();
    } catch (const Error& e) {
        return usage_error(e.what());
    }
    return std::nullopt;
}

int CommandLine::usage_error(const std::string& message) const {
    fmt::print(stderr, "{}: {}\n", m_program, message);
    return kExitUsage;
}

int run_program(const std::string& program, const std::function<int()>& body) {
    prepare_heap();
    try {
        return body();
    } catch (const UsageError& e) {
        fmt::print(stderr, "{}: {}\n", program, e.what());
        return kExitUsage;
    } catch (const std::exception& e) {
        fmt::print(stderr, "{}: {}\n", program, e.what());
        return kExitBadInput;
    }
}

void check_sampling(const RenderSettings& s, const CommonOptions& o) {
    const std::string pattern(pixel_pattern_name(s.pattern));
    const std::string whose = o.aa ? "--aa " + pattern : "the scene's anti-aliasing, " + pattern + ",";
    const bool square_pattern = s.pattern == PixelPattern::grid || s.pattern == PixelPattern::jittered;
    if (o.spp) {
        const int n = *o.spp;
        if (s.pattern == PixelPattern::none && n > 1)
            throw UsageError(
                fmt::format("--spp {} needs --aa random|jittered|grid|sobol: {} takes one sample, in the "
                            "pixel's centre",
                            n, whose));
        if (s.pattern == PixelPattern::adaptive)
            throw UsageError(
                fmt::format("--spp {} needs --aa random|jittered|grid|sobol: {} picks its samples itself "
                            "(--aa-depth and --aa-threshold tune it)",
                            n, whose));
        if (square_pattern && !is_square(n))
            throw UsageError(
                fmt::format("--spp {}: {} needs a square number of samples per pixel ({}); --aa random "
                            "takes any number",
                            n, whose, nearest_squares(n)));
    } else if (o.aa && square_pattern && !is_square(s.spp)) {
        throw UsageError(
            fmt::format("--aa {} needs a square number of samples per pixel, and the scene asks for {}: "
                        "give --spp {}",
                        pattern, s.spp, nearest_squares(s.spp)));
    }
    if ((o.aa_threshold || o.aa_depth) && s.pattern != PixelPattern::adaptive)
        throw UsageError(fmt::format("{} applies to adaptive anti-aliasing only, and {} not adaptive",
                                     o.aa_depth ? "--aa-depth" : "--aa-threshold",
                                     o.aa ? "--aa " + pattern + " is" : "the scene's, " + pattern + ", is"));
}

void prepare_output(const fs::path& output) {
    const fs::path folder = output.parent_path();
    if (folder.empty()) return;
    std::error_code ec;
    if (fs::is_directory(folder, ec)) return;
    if (fs::exists(folder, ec)) throw Error(file_error_message(output, "'" + folder.string() + "' is not a folder"));
    const fs::path above = folder.parent_path();
    if (!above.empty() && !fs::is_directory(above, ec))
        throw Error(file_error_message(output, "its folder '" + folder.string() + "' does not exist, nor does '" +
                                                   above.string() + "'; create it first"));
    // The folder above exists: make the last one, as a render into a new folder of an existing one expects.
    fs::create_directory(folder, ec);
    if (ec) throw Error(file_error_message(output, "cannot create its folder: " + ec.message()));
}

}  // namespace rtlab::app
