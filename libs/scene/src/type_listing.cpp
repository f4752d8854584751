#include <rtlab/scene/type_listing.hpp>

#include <cmath>
#include <map>

namespace rtlab {

namespace {

// Each registry with its heading, in the order a scene file uses them.
template <class F>
void each_registry(const SceneRegistries& r, F&& f) {
    f("textures", r.textures);
    f("materials", r.materials);
    f("lights", r.lights);
    f("shapes", r.shapes);
    f("tone operators", r.tone_operators);
    f("environments", r.environments);
}

// The shared groups of a registry's types, each with its parameters (taken from the first type using it).
template <class Registry>
std::map<std::string, std::vector<ParamSpec>> groups_of(const Registry& registry) {
    std::map<std::string, std::vector<ParamSpec>> out;
    for (const auto& name : registry.names()) {
        std::map<std::string, std::vector<ParamSpec>> mine;
        for (const ParamSpec& p : registry.spec(name).params())
            if (!p.group.empty()) mine[p.group].push_back(p);
        for (auto& [group, params] : mine) out.try_emplace(group, std::move(params));
    }
    return out;
}

std::string cell(std::string text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

std::string number_text(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

std::string values_text(const ParamSpec& p) {
    if (p.kind == ParamKind::word) {
        std::string out;
        for (const auto& w : p.words) out += (out.empty() ? "" : ", ") + ("`" + w + "`");
        return out;
    }
    if (std::isinf(p.lo) && std::isinf(p.hi)) return p.unit;
    std::string r = std::isinf(p.hi)   ? ">= " + number_text(p.lo)
                    : std::isinf(p.lo) ? "<= " + number_text(p.hi)
                                       : "[" + number_text(p.lo) + ", " + number_text(p.hi) + "]";
    return p.unit.empty() ? r : r + " " + p.unit;
}

void table(std::string& out, const std::vector<ParamSpec>& params, bool with_groups) {
    out += "| key | kind | default | values | what it is |\n|---|---|---|---|---|\n";
    for (const ParamSpec& p : params) {
        if (!with_groups && !p.group.empty()) continue;
        out += "| `" + p.name + "` | " + param_kind_name(p.kind) + " | " +
               (p.required ? std::string("required") : cell(p.default_value)) + " | " + cell(values_text(p)) + " | " +
               cell(p.doc) + " |\n";
    }
}

}  // namespace

std::string list_types(const SceneRegistries& registries, bool verbose) {
    std::string out;
    each_registry(registries, [&](const char* heading, const auto& registry) {
        out += std::string(heading) + ":\n";
        for (const auto& name : registry.names()) {
            const TypeSpec& spec = registry.spec(name);
            out += "  " + name + (spec.doc().empty() ? "" : ": " + spec.doc()) + "\n";
            if (verbose) out += describe_params(spec, false, "      ");
        }
        if (!verbose) return;
        for (const auto& [group, params] : groups_of(registry)) {
            out += "  every " + group + " also takes:\n";
            for (const ParamSpec& p : params) out += "      " + describe_param(p) + "\n";
        }
    });
    return out;
}

std::string markdown_type_tables(const SceneRegistries& registries) {
    std::string out;
    each_registry(registries, [&](const char* heading, const auto& registry) {
        out += "### " + std::string(heading) + "\n\n";
        for (const auto& [group, params] : groups_of(registry)) {
            out += "Every " + group + " type also takes:\n\n";
            table(out, params, true);
            out += "\n";
        }
        for (const auto& name : registry.names()) {
            const TypeSpec& spec = registry.spec(name);
            out += "#### `" + name + "`\n\n" + (spec.doc().empty() ? "" : cell(spec.doc()) + "\n\n");
            bool own = false;
            for (const ParamSpec& p : spec.params()) own = own || p.group.empty();
            if (own) {
                table(out, spec.params(), false);
            } else {
                out += "No parameters of its own.\n";
            }
            out += "\n";
        }
    });
    return out;
}

}  // namespace rtlab
