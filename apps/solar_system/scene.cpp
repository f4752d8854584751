#include "scene.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/geometry/disk.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/geometry/transform.hpp>
#include <rtlab/render/texture_level.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace rtlab::solar {

namespace {

constexpr float kFovDegrees = 50.0f;

float radians(float degrees) { return degrees * kPi / 180.0f; }

LevelOfDetail& levels_of(const std::shared_ptr<Texture>& texture) {
    auto* levels = dynamic_cast<LevelOfDetail*>(texture.get());
    if (!levels) throw Error("solar system: a texture without levels of detail");
    return *levels;
}

}  // namespace

const std::vector<Body>& bodies() {
    static const std::vector<Body> kBodies = {
        {"sun", "sun.jpg", 3.0f, 0.0f, 0.0f, 7.0f, 0.05f, {{0.62, 0.25, 0.03}, {0.62, 0.5, 0.12}, 6.0}},
        {"mercury", "mercury.jpg", 0.35f, 5.2f, 160.0f, 0.0f, 0.2f, {{0.25, 0.23, 0.22}, {0.6, 0.57, 0.53}, 8.0}},
        {"venus", "venus.jpg", 0.6f, 7.0f, 30.0f, 3.0f, 0.1f, {{0.7, 0.55, 0.3}, {0.95, 0.85, 0.6}, 3.0}},
        {"earth", "earth.jpg", 0.65f, 9.2f, 200.0f, 23.4f, 1.0f, {{0.05, 0.12, 0.4}, {0.25, 0.45, 0.15}, 3.0}},
        {"mars", "mars.jpg", 0.45f, 11.5f, 340.0f, 25.2f, 1.0f, {{0.45, 0.18, 0.08}, {0.8, 0.45, 0.25}, 5.0}},
        {"jupiter", "jupiter.jpg", 1.7f, 15.5f, 125.0f, 3.1f, 2.0f, {{0.55, 0.4, 0.3}, {0.95, 0.88, 0.78}, 4.0}},
        {"saturn", "saturn.jpg", 1.4f, 21.0f, 40.0f, 26.7f, 2.0f, {{0.7, 0.6, 0.4}, {0.95, 0.88, 0.65}, 3.0}},
        {"uranus", "uranus.jpg", 0.95f, 26.0f, 100.0f, 97.8f, 1.5f, {{0.55, 0.8, 0.85}, {0.7, 0.9, 0.92}, 2.0}},
        {"neptune", "neptune.jpg", 0.9f, 30.0f, 70.0f, 28.3f, 1.5f, {{0.15, 0.25, 0.75}, {0.35, 0.5, 0.95}, 3.0}},
    };
    return kBodies;
}

Params planet_map_params(const TextureRegistry& textures, std::size_t body, const std::string& filename) {
    Params p;
    if (filename.empty()) {
        const ProceduralLook& look = bodies().at(body).look;
        Params noise;
        noise.set("pattern", std::string("fbm"))
            .set("scale", look.scale)
            .set("seed", static_cast<double>(body + 1))
            .set("color1", look.color1)
            .set("color2", look.color2);
        p.set_object<Texture>("bake", textures.create("perlin", std::move(noise)));
        p.set("bake_size", Params::List{kFallbackWidth, kFallbackHeight});
    } else {
        p.set("filename", filename);
    }
    // u is the longitude and wraps; v is the latitude and stops at the poles.
    p.set("wrap_v", std::string("clamp")).set("lod", 0.0);
    if (body == 0) p.set("intensity", static_cast<double>(kSunEmission));
    return p;
}

Params ring_params(const TextureRegistry& textures, const std::string& filename) {
    Params p;
    if (filename.empty()) {
        // Bands across the ring (u runs from its inner to its outer edge); their grey is the opacity.
        Params bands;
        bands.set("dimension", 2.0)
            .set("pattern", std::string("marble"))
            .set("stripes", 9.0)
            .set("color1", Params::List{0.3, 0.26, 0.2})
            .set("color2", Params::List{0.9, 0.82, 0.65});
        p.set_object<Texture>("bake", textures.create("perlin", std::move(bands)));
        p.set("bake_size", Params::List{512.0, 8.0});
    } else {
        p.set("filename", filename);
    }
    p.set("wrap", std::string("clamp")).set("lod", 0.0);
    return p;
}

Params sky_params(const TextureRegistry& textures, const std::string& folder) {
    Params p;
    if (folder.empty()) {
        Params stars;
        stars.set("resolution", 512.0).set("density", 0.0025).set("seed", 7.0);
        p.set_object<Texture>("bake", textures.create("stars", std::move(stars)));
        p.set("bake_size", 512.0);
    } else {
        p.set("folder", folder);
    }
    p.set("lod", 0.0);
    return p;
}

SolarAssets load_solar_assets(const DataPath& data, bool procedural) {
    const TextureRegistry textures = make_texture_registry();
    SolarAssets assets;
    auto find = [&](const std::string& name) -> std::string {
        const auto f = procedural ? std::nullopt : data.find(name);
        assets.uses.push_back({name, f});
        return f ? f->path.string() : std::string();
    };
    for (std::size_t i = 0; i < bodies().size(); ++i) {
        const std::string file = find("textures/" + std::string(bodies()[i].texture));
        assets.maps.push_back(textures.create("image", planet_map_params(textures, i, file)));
    }
    assets.ring = textures.create("image", ring_params(textures, find(kRingName)));
    // The six faces from one folder, or the procedural field: never a cube of faces from different sources.
    const std::string sky = kSkyFolder + std::string("/");
    const auto px = procedural ? std::nullopt : data.find(sky + "px.jpg");
    std::string folder = px ? px->path.parent_path().string() : std::string();
    for (const char* face : {"nx", "py", "ny", "pz", "nz"})
        if (!folder.empty() &&
            !std::filesystem::is_regular_file(std::filesystem::path(folder) / (face + std::string(".jpg"))))
            folder.clear();
    assets.uses.push_back({sky, folder.empty() ? std::nullopt : px});
    assets.sky = textures.create("cubemap", sky_params(textures, folder));
    assets.real_textures =
        std::all_of(assets.uses.begin(), assets.uses.end(), [](const AssetUse& u) { return u.file.has_value(); });
    assets.note = procedural ? "data: procedural textures (asked for)" : describe_sources(assets.uses);
    return assets;
}

CameraSpec solar_camera(const SolarView& view) {
    const float t = static_cast<float>(view.frame) / static_cast<float>(view.frames);
    CameraSpec camera;
    const float angle = radians(90.0f) + 2.0f * kPi * t;
    camera.eye = {34.0f * std::cos(angle), 11.0f, 34.0f * std::sin(angle)};
    camera.look_at = {0.0f, -1.0f, 0.0f};
    camera.vertical_fov_degrees = kFovDegrees;
    camera.width = view.width;
    camera.height = view.height;
    return camera;
}

BodyPlacement body_placement(std::size_t i, const SolarView& view) {
    const float t = static_cast<float>(view.frame) / static_cast<float>(view.frames);
    const Body& b = bodies().at(i);
    // Kepler's third law for the angular speed, scaled so that Mercury makes a quarter turn per sequence.
    const float speed = b.orbit > 0.0f ? 0.25f * std::pow(bodies()[1].orbit / b.orbit, 1.5f) : 0.0f;
    const float angle = radians(b.phase_degrees) + 2.0f * kPi * speed * t;
    const Vec3 centre(b.orbit * std::cos(angle), 0.0f, -b.orbit * std::sin(angle));
    return {centre, Vec3(0.0f, b.phase_degrees + 360.0f * b.turns * t, b.tilt_degrees), b.radius};
}

RenderJob make_solar_job(const SolarAssets& assets, const SolarView& view, std::vector<BodyOnScreen>* on_screen) {
    if (view.frames < 1 || view.frame < 0 || view.frame >= view.frames)
        throw Error("solar system: frame " + std::to_string(view.frame) + " is not in 0.." +
                    std::to_string(view.frames - 1));
    if (assets.maps.size() != bodies().size() || !assets.ring || !assets.sky)
        throw Error("solar system: assets not loaded");
    const MaterialRegistry materials = make_material_registry();
    const LightRegistry lights = make_light_registry();

    const CameraSpec camera = solar_camera(view);
    const auto pinhole = std::make_shared<PinholeCamera>(camera);
    const float tan_half = std::tan(radians(0.5f * kFovDegrees));
    const float aspect = static_cast<float>(view.width) / static_cast<float>(view.height);
    const float pixels_per_tan = 0.5f * static_cast<float>(view.height) / tan_half;
    // The levels: as a scene file's "lod": "auto" (rtlab/render/texture_level.hpp), or 0 unfiltered.
    auto level = [&](float lod) { return view.filter_maps ? lod : 0.0f; };

    std::vector<SceneObject> objects;
    for (std::size_t i = 0; i < bodies().size(); ++i) {
        const Body& b = bodies()[i];
        const BodyPlacement place = body_placement(i, view);
        const Mat4 to_world = scene_transform(place.centre, place.rotate_degrees, Vec3(place.radius));
        LevelOfDetail& levels = levels_of(assets.maps[i]);
        levels.set_lod(level(surface_texture_lod(camera, sphere_footprint(to_world, Point3(0.0f), 1.0f),
                                                 levels.texels_u(), view.samples_per_pixel)));
        if (on_screen) {
            const Vec3 v = place.centre - camera.eye;
            const float depth = glm::dot(v, pinhole->forward()), distance = glm::length(v);
            const float radius_pixels =
                distance > b.radius ? b.radius / std::sqrt(distance * distance - b.radius * b.radius) * pixels_per_tan
                                    : static_cast<float>(view.height);
            const float x = glm::dot(v, pinhole->right()) / depth, y = glm::dot(v, pinhole->up()) / depth;
            on_screen->push_back({b.name,
                                  {(x / (tan_half * aspect) + 1.0f) * 0.5f * static_cast<float>(view.width),
                                   (1.0f - y / tan_half) * 0.5f * static_cast<float>(view.height)},
                                  radius_pixels,
                                  levels.lod(),
                                  depth > 0.0f});
        }
        const auto shape = std::make_shared<Instance>(std::make_shared<Sphere>(Point3(0.0f), 1.0f), to_world);
        Params p;
        SurfaceFlags flags;
        if (i == 0) {
            // The Sun glows and lets its light out: the point light sits inside it, so it casts no shadows.
            p.set("albedo", 0.0).set_object<Texture>("emission", assets.maps[i]);
            flags.casts_shadows = false;
        } else {
            p.set_object<Texture>("albedo", assets.maps[i]);
        }
        objects.push_back({shape, materials.create("lambert", std::move(p)), flags, b.name});
    }

    // Saturn's rings: an annulus in its equatorial plane, colour from the strip's RGB and holes from its alpha.
    {
        const std::size_t saturn = 6;
        const BodyPlacement place = body_placement(saturn, view);
        const Vec3 normal = Vec3(glm::rotate(Mat4(1.0f), glm::radians(place.rotate_degrees.z), Vec3(0, 0, 1)) *
                                 Vec4(0.0f, 1.0f, 0.0f, 0.0f));
        const float outer = kRingOuter * place.radius, inner = kRingInner * place.radius;
        LevelOfDetail& levels = levels_of(assets.ring);
        levels.set_lod(level(surface_texture_lod(camera, disk_footprint(Mat4(1.0f), place.centre, outer, inner),
                                                 levels.texels_u(), view.samples_per_pixel)));
        Params p;
        p.set_object<Texture>("albedo", assets.ring).set_object<Texture>("opacity", assets.ring);
        objects.push_back({std::make_shared<Disk>(place.centre, normal, outer, inner),
                           materials.create("lambert", std::move(p)),
                           {},
                           "saturn rings"});
    }

    RenderJob job;
    job.camera = pinhole;
    job.scene = std::make_shared<Scene>(std::move(objects));
    Params sunlight;
    sunlight.set("position", Params::List{0.0, 0.0, 0.0}).set("intensity", 1.1);
    Params ambient;
    ambient.set("intensity", 0.015);
    job.lights = {lights.create("point", std::move(sunlight)), lights.create("ambient", std::move(ambient))};
    job.whitted.convention = Convention::classic;
    job.whitted.max_depth = 2;
    LevelOfDetail& sky = levels_of(assets.sky);
    sky.set_lod(level(environment_texture_lod(camera, sky.texels_u(), view.samples_per_pixel)));
    job.whitted.environment = assets.sky;
    job.settings.pattern = PixelPattern::jittered;
    job.settings.spp = 4;
    return job;
}

}  // namespace rtlab::solar
