#pragma once
// Scenes the scene and render_job tests share: materials and lights by name, and a seeded scene of about a
// hundred spheres and quads with mirrors and glass.
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/render/scene.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>

#include <cstddef>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace rtlab::test {

/// SceneOptions::tree_threshold for a plain list at any size.
inline constexpr std::size_t kAlwaysList = std::numeric_limits<std::size_t>::max();

inline std::shared_ptr<const Material> material(const std::string& name, Params p = {}) {
    static const MaterialRegistry registry = make_material_registry();
    return registry.create(name, std::move(p));
}
inline std::shared_ptr<const Light> light(const std::string& name, Params p = {}) {
    static const LightRegistry registry = make_light_registry();
    return registry.create(name, std::move(p));
}
inline Params::List list(const Vec3& v) { return {v.x, v.y, v.z}; }
inline std::shared_ptr<const Material> lambert(const RGB& albedo) {
    Params p;
    p.set("albedo", Params::List{albedo.r, albedo.g, albedo.b});
    return material("lambert", p);
}
inline std::shared_ptr<const Light> point_light(const Point3& at, float intensity) {
    Params p;
    p.set("position", list(at)).set("intensity", intensity);
    return light("point", p);
}

/// A ray from around the random scenes' objects in a random direction; half are shadow-ray-like segments.
inline Ray random_ray(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const Point3 o(8.0f * u(rng), 2.5f + 3.0f * u(rng), -10.0f + 8.0f * u(rng));
    Vec3 d(u(rng), u(rng), u(rng));
    if (glm::dot(d, d) < 1e-4f) d = Vec3(0, 0, -1);
    Ray r{o, glm::normalize(d), 0.0f, kInfinity};
    if (u(rng) > 0.5f) r.tmax = 1.0f + 4.0f * (u(rng) + 1.0f);  // shadow-ray-like segments
    return r;
}

/// `spheres` random spheres over a floor and `quads` random quads, a tenth of each mirror and a tenth glass
/// (kinds by index, so every seed has both), inside [-5, 5] x [0, 5] x [-15, -5].
inline std::vector<SceneObject> random_objects(int spheres, int quads, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const auto mirror = material("mirror");
    const auto glass = material("glass");
    std::vector<SceneObject> objects;
    objects.push_back({std::make_shared<Quad>(Point3(-50, 0, 20), Vec3(100, 0, 0), Vec3(0, 0, -100)),
                       lambert(RGB(0.6f, 0.6f, 0.5f)),
                       {},
                       "floor"});
    auto pick = [&](int i) {
        if (i % 10 == 3) return mirror;
        if (i % 10 == 7) return glass;
        return lambert(RGB(0.2f + 0.8f * u(rng), 0.2f + 0.8f * u(rng), 0.2f + 0.8f * u(rng)));
    };
    for (int i = 0; i < spheres; ++i) {
        const Point3 c(-5.0f + 10.0f * u(rng), 0.2f + 4.0f * u(rng), -15.0f + 10.0f * u(rng));
        objects.push_back({std::make_shared<Sphere>(c, 0.15f + 0.5f * u(rng)), pick(i), {}, "sphere"});
    }
    for (int i = 0; i < quads; ++i) {
        const Point3 c(-5.0f + 10.0f * u(rng), 0.2f + 4.0f * u(rng), -15.0f + 10.0f * u(rng));
        const Vec3 a(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f), b(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
        objects.push_back({std::make_shared<Quad>(c, 1.5f * a, 1.5f * b), pick(i), {}, "quad"});
    }
    return objects;
}

}  // namespace rtlab::test
