#include <rtlab/scene/scene_registries.hpp>

namespace rtlab {

SceneRegistries SceneRegistries::builtins() {
    SceneRegistries r;
    register_builtins(r.textures);
    register_builtins(r.materials);
    register_builtins(r.lights);
    register_builtins(r.shapes);
    register_builtins(r.tone_operators);
    register_builtins(r.environments);
    return r;
}

}  // namespace rtlab
