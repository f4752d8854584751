#pragma once
/// \brief The one command-line layer of every rtlab app: the flags they share (-o, --width, --spp, ...), each
/// value checked here with a message that names the program and the flag, "did you mean" for a mistyped
/// flag, and one set of exit statuses. Apps add their own flags through the same typed helpers.
#include <rtlab/core/error.hpp>
#include <rtlab/render/renderer.hpp>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::app {

/// The exit statuses of every rtlab app.
inline constexpr int kExitDone = 0;
inline constexpr int kExitBadInput = 1;       ///< a bad scene, mesh, image or data file; a failed write
inline constexpr int kExitUsage = 2;          ///< a bad command line
inline constexpr int kExitInterrupted = 130;  ///< Ctrl-C: what was rendered is written

/// \brief A bad command-line value: the app prints "PROGRAM: MESSAGE" and exits with kExitUsage.
class UsageError : public Error {
public:
    using Error::Error;
};

/// \brief The flags every rendering app shares. An unset optional keeps the scene's own choice.
struct CommonOptions {
    std::filesystem::path output;  ///< -o; an app may set its default before add_common
    /// Extensions -o accepts besides the image formats (".rtshare" for rtlab-render); set before add_common.
    std::vector<std::string> other_outputs;
    /// --width, --height. An app that sets both before add_common gets both after parsing (one flag alone
    /// keeps the default's aspect ratio); rtlab-render leaves them unset (the scene's size).
    std::optional<int> width, height;
    std::optional<std::string> aa;          ///< none, grid, random, jittered, adaptive
    std::optional<int> spp;                 ///< exactly this many samples per pixel
    std::optional<float> aa_threshold;      ///< adaptive: colour difference that splits a square
    std::optional<int> aa_depth;            ///< adaptive: subdivision depth
    std::optional<int> max_depth;           ///< reflection and refraction depth
    std::optional<std::string> integrator;  ///< whitted | direct | path | photon | sppm
    std::optional<int> threads;             ///< 0: every core
    std::optional<std::uint64_t> seed;
    std::optional<std::string> tonemap;  ///< a tone operator name or "none"
    bool quiet = false;
    bool no_packets = false;  ///< --no-packets: one camera sample at a time (RenderSettings::packets false)
    std::vector<std::filesystem::path> data_dirs;

    int threads_or_all() const { return threads.value_or(0); }
};

/// \brief A program's command line: CLI11 underneath, with this layer's checks and messages on top.
class CommandLine {
public:
    CommandLine(std::string program, const std::string& description);
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    const std::string& program() const { return m_program; }
    /// For what the helpers below do not cover (a help footer, say).
    CLI::App& app() { return m_app; }

    /// A whole number in [lo, hi]: "--spp: must be in [1, 4096], not 0".
    void add_integer(const std::string& flags, std::optional<int>& target, int lo, int hi, const std::string& help);
    /// A number in [lo, hi].
    void add_number(const std::string& flags, std::optional<double>& target, double lo, double hi,
                    const std::string& help);
    void add_number(const std::string& flags, std::optional<float>& target, double lo, double hi,
                    const std::string& help);
    /// One of `words`: "--aa: 'jitered' is not one of none, ...; did you mean 'jittered'?".
    void add_word(const std::string& flags, std::optional<std::string>& target, std::vector<std::string> words,
                  const std::string& help);
    void add_word(const std::string& flags, std::string& target, std::vector<std::string> words,
                  const std::string& help);
    /// Any text (a file name); `check` may throw UsageError for a bad one.
    void add_text(const std::string& flags, std::string& target, const std::string& help,
                  std::function<void(const std::string&)> check = {});
    /// A repeatable option: one value per occurrence (`--plugin a.so --plugin b.so scene.json`), never
    /// swallowing the arguments after it.
    void add_list(const std::string& flags, std::vector<std::filesystem::path>& target, const std::string& help);
    void add_flag(const std::string& flags, bool& target, const std::string& help);
    /// A positional argument (at most one value).
    void add_positional(const std::string& name, std::string& target, const std::string& help);
    /// Positional arguments, any number (rtlab-merge's share files).
    void add_positionals(const std::string& name, std::vector<std::filesystem::path>& target, const std::string& help);

    /// Adds -o, --width, --height, --aa, --spp, --aa-threshold, --aa-depth, --depth, --threads, --seed,
    /// --tonemap (one of `tone_operators` or none), --quiet, --no-packets and --data-dir, bound to `options`.
    void add_common(CommonOptions& options, const std::vector<std::string>& tone_operators);

    /// Parses and checks the command line. Returns nothing when the app should go on; else its exit status:
    /// 0 after --help, kExitUsage after a bad command line ("PROGRAM: problem" on stderr).
    std::optional<int> parse(int argc, const char* const* argv);

    /// Prints "PROGRAM: message" (and a pointer to --help) on stderr and returns kExitUsage.
    int usage_error(const std::string& message) const;

    /// The flags known to this command line ("--spp", "-o"), for "did you mean".
    std::vector<std::string> flag_names() const;

private:
    struct Check {
        CLI::Option* option;
        std::string name;  // as messages show it: the first name given ("-o", "--spp")
        const std::string* raw;
        std::function<void(const std::string& name, const std::string& raw)> apply;
    };
    void add_checked(const std::string& flags, const std::string& type, const std::string& help,
                     std::function<void(const std::string&, const std::string&)> apply);
    void check_extras() const;
    /// The first value flag followed by no value ("--width" last, or before another flag).
    std::optional<std::string> flag_without_value(int argc, const char* const* argv) const;

    std::string m_program;
    CLI::App m_app;
    std::deque<std::string> m_raw;  // the values as typed, one per checked option (stable addresses)
    std::vector<Check> m_checks;
    std::vector<std::function<void()>> m_after;  // checks of several flags together, after each one's own
};

/// Runs an app's body, the heap prepared for it first (prepare_heap): returns its status; a UsageError becomes
/// "PROGRAM: message" and kExitUsage, any other exception "PROGRAM: message" and kExitBadInput.
int run_program(const std::string& program, const std::function<int()>& body);

/// Checks that --aa and --spp (applied to `settings` already) give exactly the samples asked for: --spp with
/// a pattern of one sample (none) or with adaptive, or a non-square count for grid and jittered, is a
/// UsageError saying what to give instead. Values that all come from the scene are the scene's business.
void check_sampling(const RenderSettings& settings, const CommonOptions& options);

/// Makes sure `output` can be written before any work is done: its folder exists, or is created when the
/// folder above it exists; otherwise rtlab::Error naming the folder (exit status 1).
void prepare_output(const std::filesystem::path& output);

}  // namespace rtlab::app
