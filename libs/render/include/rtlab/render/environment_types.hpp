#pragma once
/// \brief Environments by name, for a scene's "environment" key: "envmap", an equirectangular or cube map read
/// from files (EXR, HDR, PFM, PNG, JPG). They live in render because reading EXR does (image_input.hpp).
#include <rtlab/core/registry.hpp>
#include <rtlab/shading/emitter.hpp>

namespace rtlab {

using EnvironmentRegistry = Registry<EnvironmentEmitter>;

/// Registers "envmap"; its doc() and declaration list the parameters.
void register_builtins(EnvironmentRegistry& registry);

/// A registry with category "environment" and every built-in registered.
EnvironmentRegistry make_environment_registry();

}  // namespace rtlab
