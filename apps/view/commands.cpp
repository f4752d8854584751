#include "commands.hpp"

#include <rtlab/core/error.hpp>

#include <map>
#include <sstream>

namespace rtlab::view {

std::optional<Command> parse_command(const std::string& line, const std::string& where) {
    const std::string text = line.substr(0, line.find('#'));
    std::istringstream in(text);
    Command c;
    if (!(in >> c.name)) return std::nullopt;
    for (std::string word; in >> word;) c.args.push_back(word);
    static const std::map<std::string, std::size_t> arity{
        {"wait", 0},  {"screenshot", 1},   {"save", 1}, {"orbit", 2},    {"pan", 2},  {"dolly", 1},
        {"reset", 0}, {"print-camera", 0}, {"tone", 1}, {"exposure", 1}, {"view", 1}, {"reference", 1},
        {"zoom", 1},  {"inspect", 2},      {"spp", 1},  {"stats", 0},    {"quit", 0}};
    const auto it = arity.find(c.name);
    if (it == arity.end()) throw Error(where + ": unknown command '" + c.name + "'");
    if (c.name == "wait") {
        const bool ok = (c.args.size() == 2 && c.args[0] == "pass") ||
                        (c.args.size() == 1 && (c.args[0] == "reloaded" || c.args[0] == "error"));
        if (!ok) throw Error(where + ": wait takes 'pass N', 'reloaded' or 'error'");
    } else if (c.args.size() != it->second) {
        throw Error(where + ": " + c.name + " takes " + std::to_string(it->second) + " argument(s), got " +
                    std::to_string(c.args.size()));
    }
    return c;
}

}  // namespace rtlab::view
