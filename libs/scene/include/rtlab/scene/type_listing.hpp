#pragma once
/// \brief The registered types and their declared parameters as text: `rtlab-render --list [--verbose]` and the
/// parameter tables of docs/scene-format.md (generated from the same declarations, checked by a test).
#include <rtlab/scene/scene_registries.hpp>

#include <string>

namespace rtlab {

/// One section per registry ("textures:", "materials:", ...), one line per type with its doc; with
/// `verbose`, every declared parameter under its type, and the parameters a group of types shares (every
/// material's kr, kt, ...) once per group.
std::string list_types(const SceneRegistries& registries, bool verbose);

/// Markdown: a table of parameters for each type of each registry (name, kind, default, range or words,
/// doc), shared groups once.
std::string markdown_type_tables(const SceneRegistries& registries);

}  // namespace rtlab
