#include "scene.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/core/sample_hash.hpp>
#include <rtlab/geometry/disk.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/textures/cube_map.hpp>
#include <rtlab/textures/image_texture.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab::solar {

namespace {

constexpr float kFovDegrees = 50.0f;
constexpr float kSunEmission = 1.6f;  // the Sun map's linear values reach ~0.6; this makes its disc glow
constexpr float kRingInner = 1.25f, kRingOuter = 2.3f;  // in Saturn radii (the D ring to beyond the A ring)

float radians(float degrees) { return degrees * kPi / 180.0f; }

// Planet colours for the procedural maps: the two ends of a noise blend and how banded the body is.
struct ProceduralLook {
    RGB a, b;
    float bands;  // 0: rocky (noise only); > 0: bands of latitude (gas giants)
    float scale;
};

ProceduralLook look(int body) {
    static const ProceduralLook kLooks[] = {
        {{0.62f, 0.25f, 0.03f}, {0.62f, 0.5f, 0.12f}, 0.0f, 6.0f},  // sun
        {{0.25f, 0.23f, 0.22f}, {0.6f, 0.57f, 0.53f}, 0.0f, 8.0f},  // mercury
        {{0.7f, 0.55f, 0.3f}, {0.95f, 0.85f, 0.6f}, 3.0f, 3.0f},    // venus
        {{0.05f, 0.12f, 0.4f}, {0.25f, 0.45f, 0.15f}, 0.0f, 3.0f},  // earth: sea and land
        {{0.45f, 0.18f, 0.08f}, {0.8f, 0.45f, 0.25f}, 0.0f, 5.0f},  // mars
        {{0.55f, 0.4f, 0.3f}, {0.95f, 0.88f, 0.78f}, 14.0f, 4.0f},  // jupiter
        {{0.7f, 0.6f, 0.4f}, {0.95f, 0.88f, 0.65f}, 10.0f, 3.0f},   // saturn
        {{0.55f, 0.8f, 0.85f}, {0.7f, 0.9f, 0.92f}, 4.0f, 2.0f},    // uranus
        {{0.15f, 0.25f, 0.75f}, {0.35f, 0.5f, 0.95f}, 6.0f, 3.0f},  // neptune
    };
    return kLooks[body];
}

// An equirectangular map of a noise blend on the unit sphere (so it has no seam), banded for gas giants.
Image procedural_map(int body, const TextureRegistry& textures) {
    const ProceduralLook l = look(body);
    Params p;
    p.set("pattern", std::string("fbm")).set("scale", static_cast<double>(l.scale)).set("seed", body + 1.0);
    const auto noise = textures.create("perlin", std::move(p));
    const int w = 512, h = 256;
    Image map(w, h);
    for (int y = 0; y < h; ++y) {
        const float lat = kPi * (0.5f - (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
        for (int x = 0; x < w; ++x) {
            const float lon = 2.0f * kPi * (static_cast<float>(x) + 0.5f) / static_cast<float>(w);
            TextureLookup q;
            q.point = {std::cos(lat) * std::cos(lon), std::sin(lat), -std::cos(lat) * std::sin(lon)};
            float t = scalar(noise->eval(q));
            if (l.bands > 0.0f) t = 0.5f + 0.35f * std::sin(l.bands * lat + 3.0f * (t - 0.5f)) + 0.3f * (t - 0.5f);
            t = std::clamp(t, 0.0f, 1.0f);
            map.at(x, y) = l.a * (1.0f - t) + l.b * t;
        }
    }
    return map;
}

// A ring strip like saturn_ring.png: radial colour, alpha 0 at the inner edge, a gap, fading at the rim.
Image procedural_ring() {
    const int w = 512;
    Image ring(w, 4);
    ring.add_alpha();
    for (int x = 0; x < w; ++x) {
        const float r = (static_cast<float>(x) + 0.5f) / static_cast<float>(w);
        float a = r < 0.05f ? 0.0f : (r < 0.3f ? 0.3f : 0.9f);
        if (std::abs(r - 0.68f) < 0.03f) a = 0.1f;  // a Cassini division
        if (r > 0.9f) a *= std::max(0.0f, (1.0f - r) / 0.1f);
        for (int y = 0; y < 4; ++y) {
            ring.at(x, y) = RGB(0.75f, 0.68f, 0.55f) * (0.8f + 0.2f * std::sin(60.0f * r));
            ring.alpha_at(x, y) = a;
        }
    }
    return ring;
}

// Six faces of a random star field: one texel in 400 a star of random brightness, the rest black.
std::array<Image, 6> procedural_sky() {
    std::array<Image, 6> faces;
    const int n = 512;
    for (std::uint32_t f = 0; f < 6; ++f) {
        faces[f] = Image(n, n);
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const SampleKey key{7, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), f, 0};
                if (sample_uniform(key, 0) < 1.0f / 400.0f) {
                    const float b = 0.3f + 2.0f * sample_uniform(key, 1) * sample_uniform(key, 1);
                    faces[f].at(x, y) = RGB(b, b, b * (0.85f + 0.3f * sample_uniform(key, 2)));
                }
            }
        }
    }
    return faces;
}

Vec3 orbit_position(const Body& b, float t) {
    // Kepler's third law for the angular speed, scaled so that Mercury makes a quarter turn per sequence.
    const float speed = b.orbit > 0.0f ? 0.25f * std::pow(bodies()[1].orbit / b.orbit, 1.5f) : 0.0f;
    const float angle = radians(b.phase_degrees) + 2.0f * kPi * speed * t;
    return {b.orbit * std::cos(angle), 0.0f, -b.orbit * std::sin(angle)};
}

}  // namespace

const std::vector<Body>& bodies() {
    static const std::vector<Body> kBodies = {
        {"sun", "sun.jpg", 3.0f, 0.0f, 0.0f, 7.0f, 0.05f},
        {"mercury", "mercury.jpg", 0.35f, 5.2f, 160.0f, 0.0f, 0.2f},
        {"venus", "venus.jpg", 0.6f, 7.0f, 30.0f, 3.0f, 0.1f},
        {"earth", "earth.jpg", 0.65f, 9.2f, 200.0f, 23.4f, 1.0f},
        {"mars", "mars.jpg", 0.45f, 11.5f, 340.0f, 25.2f, 1.0f},
        {"jupiter", "jupiter.jpg", 1.7f, 15.5f, 125.0f, 3.1f, 2.0f},
        {"saturn", "saturn.jpg", 1.4f, 21.0f, 40.0f, 26.7f, 2.0f},
        {"uranus", "uranus.jpg", 0.95f, 26.0f, 100.0f, 97.8f, 1.5f},
        {"neptune", "neptune.jpg", 0.9f, 30.0f, 70.0f, 28.3f, 1.5f},
    };
    return kBodies;
}

SolarAssets load_solar_assets(const SearchPath& data, bool procedural) {
    SolarAssets assets;
    const std::array<const char*, 6> face_names = {"px", "nx", "py", "ny", "pz", "nz"};
    std::vector<std::filesystem::path> planet_files;
    std::array<std::filesystem::path, 6> face_files;
    std::optional<std::filesystem::path> ring_file;
    bool found = !procedural;
    if (found) {
        for (const Body& b : bodies()) {
            const auto f = data.find(std::filesystem::path("textures") / b.texture);
            if (!f)
                found = false;
            else
                planet_files.push_back(*f);
        }
        for (std::size_t i = 0; i < 6; ++i) {
            const auto f = data.find(std::filesystem::path("textures/skybox") / (std::string(face_names[i]) + ".jpg"));
            if (!f)
                found = false;
            else
                face_files[i] = *f;
        }
        ring_file = data.find("textures/saturn_ring.png");
        if (!ring_file) found = false;
    }

    std::array<Image, 6> faces;
    Image ring;
    if (found) {
        for (const auto& f : planet_files) assets.maps.push_back(std::make_shared<MipMap>(read_image(f)));
        for (std::size_t i = 0; i < 6; ++i) faces[i] = read_image(face_files[i]);
        ring = read_image(*ring_file);
        assets.real_textures = true;
        assets.note = "textures: images from " + planet_files.front().parent_path().string();
    } else {
        const TextureRegistry textures = make_texture_registry();
        for (std::size_t i = 0; i < bodies().size(); ++i)
            assets.maps.push_back(std::make_shared<MipMap>(procedural_map(static_cast<int>(i), textures)));
        faces = procedural_sky();
        ring = procedural_ring();
        assets.note = procedural
                          ? "textures: procedural (asked for)"
                          : "textures: procedural (textures/*.jpg, textures/skybox/ and textures/saturn_ring.png "
                            "not all found in " +
                                data.describe() + ")";
    }

    assets.sky_face_size = faces[0].width();
    while (true) {
        std::array<Image, 6> next;
        const bool last = faces[0].width() <= 16;
        if (!last)
            for (std::size_t i = 0; i < 6; ++i) next[i] = downsample(faces[i]);
        assets.sky.push_back(std::make_shared<CubeMapTexture>(std::move(faces)));
        if (last) break;
        faces = std::move(next);
    }
    assets.ring.push_back(std::make_shared<Image>(std::move(ring)));
    while (assets.ring.back()->width() > 8)
        assets.ring.push_back(std::make_shared<Image>(downsample(*assets.ring.back())));
    return assets;
}

RenderJob make_solar_job(const SolarAssets& assets, const SolarView& view, std::vector<BodyOnScreen>* on_screen) {
    if (view.frames < 1 || view.frame < 0 || view.frame >= view.frames)
        throw Error("solar system: frame " + std::to_string(view.frame) + " is not in 0.." +
                    std::to_string(view.frames - 1));
    if (assets.maps.size() != bodies().size()) throw Error("solar system: assets not loaded");
    const MaterialRegistry materials = make_material_registry();
    const LightRegistry lights = make_light_registry();
    const float t = static_cast<float>(view.frame) / static_cast<float>(view.frames);

    // The camera makes one turn around the Sun over the sequence, looking slightly down at it.
    CameraSpec camera;
    const float cam_angle = radians(90.0f) + 2.0f * kPi * t;
    camera.eye = {34.0f * std::cos(cam_angle), 11.0f, 34.0f * std::sin(cam_angle)};
    camera.look_at = {0.0f, -1.0f, 0.0f};
    camera.vertical_fov_degrees = kFovDegrees;
    camera.width = view.width;
    camera.height = view.height;
    const auto pinhole = std::make_shared<PinholeCamera>(camera);
    const float tan_half = std::tan(radians(0.5f * kFovDegrees));
    const float aspect = static_cast<float>(view.width) / static_cast<float>(view.height);
    const float pixels_per_tan = 0.5f * static_cast<float>(view.height) / tan_half;
    // Averaging n samples in a pixel filters like a footprint sqrt(n) times smaller.
    const float lod_bias = -0.5f * std::log2(std::max(1.0f, view.samples_per_pixel));

    std::vector<SceneObject> objects;
    Vec3 saturn_centre(0.0f);
    Mat4 saturn_tilt(1.0f);
    float saturn_pixels = 0.0f;
    for (std::size_t i = 0; i < bodies().size(); ++i) {
        const Body& b = bodies()[i];
        const Vec3 centre = orbit_position(b, t);
        const Vec3 v = centre - camera.eye;
        const float depth = glm::dot(v, pinhole->forward());
        const float distance = glm::length(v);
        const float radius_pixels =
            distance > b.radius ? b.radius / std::sqrt(distance * distance - b.radius * b.radius) * pixels_per_tan
                                : static_cast<float>(view.height);
        const float lod =
            view.filter_maps ? planet_lod(assets.maps[i]->width(), 2.0f * radius_pixels) + lod_bias : 0.0f;
        if (on_screen) {
            const float x = glm::dot(v, pinhole->right()) / depth, y = glm::dot(v, pinhole->up()) / depth;
            on_screen->push_back({b.name,
                                  {(x / (tan_half * aspect) + 1.0f) * 0.5f * static_cast<float>(view.width),
                                   (1.0f - y / tan_half) * 0.5f * static_cast<float>(view.height)},
                                  radius_pixels,
                                  std::max(0.0f, lod),
                                  depth > 0.0f});
        }

        const Mat4 tilt = glm::rotate(Mat4(1.0f), radians(b.tilt_degrees), Vec3(0, 0, 1));
        const float spin = 2.0f * kPi * b.turns * t + radians(b.phase_degrees);
        const Mat4 to_world = glm::translate(Mat4(1.0f), centre) * tilt * glm::rotate(Mat4(1.0f), spin, Vec3(0, 1, 0)) *
                              glm::scale(Mat4(1.0f), Vec3(b.radius));
        const auto shape = std::make_shared<Instance>(std::make_shared<Sphere>(Point3(0.0f), 1.0f), to_world);
        const auto map = std::make_shared<MipTexture>(assets.maps[i], lod, i == 0 ? kSunEmission : 1.0f);
        Params p;
        SurfaceFlags flags;
        if (i == 0) {
            // The Sun glows and lets its light out: the point light sits inside it, so it casts no shadows.
            p.set("albedo", 0.0).set_object<const Texture>("emission", map);
            flags.casts_shadows = false;
        } else {
            p.set_object<const Texture>("albedo", map);
        }
        objects.push_back({shape, materials.create("lambert", std::move(p)), flags, b.name});
        if (std::string_view(b.name) == "saturn") {
            saturn_centre = centre;
            saturn_tilt = tilt;
            saturn_pixels = radius_pixels;
        }
    }

    // Saturn's rings: an annulus in its equatorial plane, colour from the strip's RGB and holes from its alpha.
    // The strip runs radially over (outer - inner) Saturn radii; its level is picked as the planets' are.
    {
        const float saturn_radius = bodies()[6].radius;
        const Vec3 normal = Vec3(saturn_tilt * glm::vec4(0, 1, 0, 0));
        const int strip = assets.ring.front()->width();
        const float ring_pixels = (kRingOuter - kRingInner) * saturn_pixels;
        const float lod = view.filter_maps && ring_pixels > 0.0f
                              ? std::log2(static_cast<float>(strip) / ring_pixels) + lod_bias
                              : 0.0f;
        const int level = std::clamp(static_cast<int>(std::lround(lod)), 0, static_cast<int>(assets.ring.size()) - 1);
        ImageTextureOptions options;
        options.wrap = WrapMode::clamp;
        const auto ring = std::make_shared<ImageTexture>(assets.ring[static_cast<std::size_t>(level)], options);
        Params p;
        p.set_object<const Texture>("albedo", ring).set_object<const Texture>("opacity", ring);
        objects.push_back(
            {std::make_shared<Disk>(saturn_centre, normal, kRingOuter * saturn_radius, kRingInner * saturn_radius),
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
    // The sky's level: a face texel about one pixel at the centre of the view.
    int sky_level = 0;
    if (view.filter_maps) {
        const float texels_per_pixel =
            static_cast<float>(assets.sky_face_size) * tan_half / static_cast<float>(view.height);
        sky_level =
            std::clamp(static_cast<int>(std::floor(std::log2(std::max(1.0f, texels_per_pixel)) + lod_bias + 0.5f)), 0,
                       static_cast<int>(assets.sky.size()) - 1);
    }
    job.whitted.environment = assets.sky[static_cast<std::size_t>(sky_level)];
    job.settings.pattern = PixelPattern::jittered;
    job.settings.spp = 4;
    return job;
}

}  // namespace rtlab::solar
