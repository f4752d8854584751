#include "scene.hpp"

#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>

namespace rtlab::whitted {

namespace {

Params::List rgb(float r, float g, float b) { return {r, g, b}; }

}  // namespace

RenderJob make_whitted_job(int width, int height) {
    const TextureRegistry textures = make_texture_registry();
    const MaterialRegistry materials = make_material_registry();
    const LightRegistry lights = make_light_registry();

    // The board: 8 x 14 tiles of one unit, a finite rectangle as in the 1980 picture.
    const float depth = 14.0f;
    Params checker;
    checker.set("tiles_u", 2.0 * kBoardHalfWidth).set("tiles_v", static_cast<double>(depth));
    checker.set("color1", rgb(0.8f, 0.04f, 0.02f)).set("color2", rgb(0.95f, 0.85f, 0.1f));
    Params board;
    board.set_object<const Texture>("kd", textures.create("checker", std::move(checker)));
    board.set("ks", 0.0).set("exponent", 1.0);

    Params mirror;
    mirror.set("kd", 0.05).set("ks", 0.6).set("exponent", 80.0).set("kr", 0.8);
    Params glass_out;
    glass_out.set("ior", 1.5);
    // The air inside the shell: index 1 inside, the glass's 1.5 outside.
    Params glass_in;
    glass_in.set("ior", 1.0).set("ior_outside", 1.5);

    std::vector<SceneObject> objects;
    objects.push_back({std::make_shared<Quad>(Point3(-kBoardHalfWidth, 0.0f, 2.0f), Vec3(2.0f * kBoardHalfWidth, 0, 0),
                                              Vec3(0, 0, -depth)),
                       materials.create("phong", std::move(board)),
                       {},
                       "checkerboard"});
    objects.push_back({std::make_shared<Sphere>(Point3(1.25f, 1.0f, -4.3f), 1.0f),
                       materials.create("phong", std::move(mirror)),
                       {},
                       "mirror sphere"});
    objects.push_back({std::make_shared<Sphere>(Point3(-0.75f, 1.3f, -1.4f), 0.85f),
                       materials.create("glass", std::move(glass_out)),
                       {},
                       "glass shell, outside"});
    objects.push_back({std::make_shared<Sphere>(Point3(-0.75f, 1.3f, -1.4f), 0.75f),
                       materials.create("glass", std::move(glass_in)),
                       {},
                       "glass shell, inside"});

    RenderJob job;
    CameraSpec camera;
    camera.eye = {0.0f, 2.0f, 4.0f};
    camera.look_at = {0.0f, 0.9f, -2.5f};
    camera.vertical_fov_degrees = 45.0f;
    camera.width = width;
    camera.height = height;
    job.camera = std::make_shared<PinholeCamera>(camera);
    job.scene = std::make_shared<Scene>(std::move(objects));

    Params sun;
    sun.set("position", rgb(-4.0f, 9.0f, 6.0f)).set("intensity", 0.9);
    Params ambient;
    ambient.set("intensity", 0.12);
    job.lights = {lights.create("point", std::move(sun)), lights.create("ambient", std::move(ambient))};

    job.whitted.convention = Convention::classic;
    job.whitted.max_depth = 8;
    job.whitted.background = RGB(0.25f, 0.5f, 0.95f);
    job.settings.pattern = PixelPattern::adaptive;
    job.settings.adaptive = AdaptiveSettings{3, 0.3f};
    return job;
}

}  // namespace rtlab::whitted
