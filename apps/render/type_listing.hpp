#pragma once
// rtlab-render --list [--verbose]: the registered types by category.
#include <rtlab/scene/scene_registries.hpp>

#include <string>

namespace rtlab::app {

/// One line per type ("  name   doc") under each category. `verbose` adds each type's own declared parameters
/// (describe_params) below it, and the parameters a group of types shares (every material's kr, kt, ...) once
/// after the category instead of under every type.
std::string list_types(const SceneRegistries& registries, bool verbose);

}  // namespace rtlab::app
