#pragma once
/// \brief The solar-system scene built in code (rtlab-solar-system), so that a test can build the same one.
#include <rtlab/core/search_path.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/textures/texture.hpp>

#include "planet_map.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace rtlab::solar {

/// \brief The images of the scene, loaded (or made) once and shared by every frame of a sequence.
struct SolarAssets {
    std::vector<std::shared_ptr<const MipMap>> maps;  ///< one per body of bodies(), the Sun first
    std::vector<std::shared_ptr<const Image>> ring;   ///< Saturn's ring strip (colour and alpha), halved per level
    std::vector<std::shared_ptr<const Texture>> sky;  ///< the star-field cube map, face size halved per level
    int sky_face_size = 0;                            ///< of level 0
    bool real_textures = false;
    std::string note;  ///< which textures are used and from where, for the app to print
};

/// Loads the planet maps, ring and star-field faces of ../shared/textures (textures/earth.jpg,
/// textures/skybox/px.jpg, ...) from `data`; when any is missing, or with `procedural`, makes procedural
/// ones instead (noise and bands per body, a random star field) and says so in the note.
SolarAssets load_solar_assets(const SearchPath& data, bool procedural = false);

/// \brief One body: a sphere of `radius` on a circular orbit of `orbit` around the Sun.
struct Body {
    const char* name;
    const char* texture;  ///< file name under textures/
    float radius, orbit, phase_degrees, tilt_degrees;
    float turns;  ///< spins about its axis over a whole sequence
};

/// The Sun and the eight planets (sizes and distances not to scale), in that order.
const std::vector<Body>& bodies();

/// \brief Which picture of the sequence, and how it is filtered.
struct SolarView {
    int width = 640, height = 480;
    int frame = 0;                   ///< 0 .. frames - 1
    int frames = 1;                  ///< the camera makes one turn around the Sun over the sequence
    bool filter_maps = true;         ///< false: planet maps and sky at full resolution (for comparison)
    float samples_per_pixel = 1.0f;  ///< more samples average more texels: the level drops by log4 of it
};

/// \brief Where a body lands in the image (for tests and the shimmer measurement).
struct BodyOnScreen {
    const char* name;
    Vec2 centre;  ///< image position (pixels, y down)
    float radius_pixels;
    float lod;      ///< the map level used
    bool in_front;  ///< in front of the camera
};

/// The job for one frame: an emissive Sun with a point light inside it that it does not shadow, the planets
/// textured through MipTextures at the level their size on screen asks for, Saturn's rings as an annulus
/// whose ring-image alpha is its opacity, and the star field as the environment. Physical units are not
/// used: the classic convention (no fall-off with distance). Jittered 4 samples per pixel by default.
/// `on_screen`, when given, receives every body's place in the image.
RenderJob make_solar_job(const SolarAssets& assets, const SolarView& view,
                         std::vector<BodyOnScreen>* on_screen = nullptr);

}  // namespace rtlab::solar
