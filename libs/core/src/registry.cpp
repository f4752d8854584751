#include <rtlab/core/registry.hpp>

namespace rtlab::detail {

void throw_unknown_name(std::string_view category, std::string_view name, const std::vector<std::string>& known) {
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw Error("unknown " + std::string(category) + " '" + std::string(name) +
                "'; known: " + (list.empty() ? std::string("(none registered)") : list));
}

void throw_duplicate_name(std::string_view category, std::string_view name) {
    throw Error(std::string(category) + " '" + std::string(name) + "' is already registered");
}

}  // namespace rtlab::detail
