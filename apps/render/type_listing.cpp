#include "type_listing.hpp"

#include <rtlab/core/param_spec.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <vector>

namespace rtlab::app {

namespace {

template <class Registry>
void list_category(std::string& out, const char* title, const Registry& registry, bool verbose) {
    if (*title) out += fmt::format("{}:\n", title);
    std::vector<const ParamSpec*> shared;
    for (const auto& name : registry.names()) {
        out += fmt::format("  {:<20} {}\n", name, registry.doc(name));
        if (!verbose) continue;
        const TypeSpec& spec = registry.spec(name);
        out += describe_params(spec, false, "      ");
        for (const ParamSpec& p : spec.params()) {
            const bool seen = std::any_of(shared.begin(), shared.end(),
                                          [&](const ParamSpec* q) { return q->group == p.group && q->name == p.name; });
            if (!p.group.empty() && !seen) shared.push_back(&p);
        }
    }
    std::stable_sort(shared.begin(), shared.end(),
                     [](const ParamSpec* a, const ParamSpec* b) { return a->group < b->group; });
    std::string group;
    for (const ParamSpec* p : shared) {
        if (p->group != group) out += fmt::format("  shared by {}:\n", group = p->group);
        out += fmt::format("      {}\n", describe_param(*p));
    }
}

}  // namespace

std::string list_types(const SceneRegistries& r, bool verbose) {
    std::string out;
    list_category(out, "shapes", r.shapes, verbose);
    list_category(out, "materials", r.materials, verbose);
    list_category(out, "textures", r.textures, verbose);
    list_category(out, "lights", r.lights, verbose);
    out += fmt::format("tone operators:\n  {:<20} {}\n", "none", "clamps to [0, 1] (the default)");
    list_category(out, "", r.tone_operators, verbose);
    return out;
}

}  // namespace rtlab::app
