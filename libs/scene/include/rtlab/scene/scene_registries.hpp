#pragma once
/// \brief Every registry a scene file draws on, in one place, so that a plugin can add to all of them.
#include <rtlab/render/environment_types.hpp>
#include <rtlab/scene/shape_registry.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/textures/texture.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

namespace rtlab {

/// \brief The textures, materials, lights, shapes, tone operators and environments a scene's `type` keys are
/// looked up in.
struct SceneRegistries {
    TextureRegistry textures{"texture"};
    MaterialRegistry materials{"material"};
    LightRegistry lights{"light"};
    ShapeRegistry shapes{"shape"};
    ToneRegistry tone_operators{"tone operator"};
    EnvironmentRegistry environments{"environment"};

    /// Registries holding every built-in type of each library.
    static SceneRegistries builtins();
};

}  // namespace rtlab
