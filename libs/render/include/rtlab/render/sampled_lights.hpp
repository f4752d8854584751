#pragma once
/// \brief The lights of a render under the sampling integrators (direct, path): every object whose material
/// emits becomes an area light, the `area` lights become emitting quads in the scene, point, spot and
/// directional lights stay delta lights, and a background colour becomes a uniform environment (or the job's
/// environment light is the environment).
#include <rtlab/render/scene.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/light_set.hpp>
#include <rtlab/shading/whitted.hpp>

#include <memory>
#include <vector>

namespace rtlab {

/// \brief A scene ready for a sampling integrator: the scene (the job's own, or a copy with the area lights'
/// quads added) and its lights.
struct SampledLights {
    std::shared_ptr<const Scene> scene;
    LightSet lights;
    /// Bounds the scene: the centre and half the diagonal of its box (radius 1 for an empty scene); the directional
    /// lights' and the environment's powers use this radius, their photons leave a disk of it.
    SceneSphere sphere;
};

/// The area light of one object: its shape (a quad, a disk, a sphere, a MeshShape, or an Instance of one of them
/// under a similarity for disks and spheres) sampled by area with its material's constant emission; nullptr for
/// an object that does not emit, emits through a texture, or whose shape has no sampler (a box, a cylinder):
/// those shine only where BSDF sampling meets them.
std::shared_ptr<const AreaEmitter> make_area_emitter(const SceneObject& object);

/// Builds the lights of `scene` and `lights` for the direct and path integrators; `whitted` gives the
/// background (black: no environment) and the convention; `environment`, when given, is the environment light
/// instead of the background, its power set for the scene's radius. Throws rtlab::Error naming what such an
/// integrator cannot honour physically: the classic convention ("convention") and ambient lights ("ambient").
SampledLights make_sampled_lights(std::shared_ptr<const Scene> scene,
                                  const std::vector<std::shared_ptr<const Light>>& lights,
                                  const WhittedOptions& whitted,
                                  std::shared_ptr<const EnvironmentEmitter> environment = nullptr);

}  // namespace rtlab
