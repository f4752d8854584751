#pragma once
/// \brief The solar-system scene built in code (rtlab-solar-system), so that a test can build the same one.
///
/// scenes/solar_system.json is the same scene as a file (frame 0 of a one-frame sequence): its textures are
/// made by the same registry types with the same parameters (an "image" with "lod": "auto", its procedural
/// "fallback" baked when the file is missing), and their levels are picked by the same functions
/// (rtlab/render/texture_level.hpp), so the two render byte-identical images.
#include <rtlab/core/data_path.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/textures/mip_map.hpp>
#include <rtlab/textures/texture.hpp>

#include <memory>
#include <string>
#include <vector>

namespace rtlab::solar {

/// \brief The procedural stand-in for a body's map: fBm noise on the sphere blending two colours,
/// baked into a kFallbackWidth x kFallbackHeight image (a "perlin" texture as a scene file's "fallback").
struct ProceduralLook {
    Params::List color1, color2;
    double scale;
};

/// \brief One body: a sphere of `radius` on a circular orbit of `orbit` around the Sun.
struct Body {
    const char* name;
    const char* texture;  ///< file name under textures/
    float radius, orbit, phase_degrees, tilt_degrees;
    float turns;  ///< spins about its axis over a whole sequence
    ProceduralLook look;
};

/// The Sun and the eight planets (sizes and distances not to scale), in that order.
const std::vector<Body>& bodies();

constexpr int kFallbackWidth = 512, kFallbackHeight = 256;  ///< of a baked procedural planet map
constexpr float kSunEmission = 1.6f;  ///< the Sun map's linear values reach ~0.6; this makes its disc glow
constexpr float kRingInner = 1.25f, kRingOuter = 2.3f;  ///< in Saturn radii (the D ring to beyond the A ring)

/// The parameters of each texture, as a scene file gives them (the file name found on the data path, or
/// the fallback when it is not): `filename` empty means the fallback.
Params planet_map_params(const TextureRegistry& textures, std::size_t body, const std::string& filename);
Params ring_params(const TextureRegistry& textures, const std::string& filename);
Params sky_params(const TextureRegistry& textures, const std::string& folder);

/// \brief The textures of the scene, made once and shared by every frame of a sequence. Each has levels
/// (rtlab::LevelOfDetail) that make_solar_job sets for its frame: render a job before making the next.
struct SolarAssets {
    std::vector<std::shared_ptr<Texture>> maps;  ///< one per body of bodies(), the Sun first
    std::shared_ptr<Texture> ring;               ///< Saturn's ring strip (colour and alpha)
    std::shared_ptr<Texture> sky;                ///< the star-field cube map
    bool real_textures = false;                  ///< every image was found
    std::vector<AssetUse> uses;                  ///< each asset's name and the file found (none: procedural)
    std::string note;  ///< one line: where each texture came from and the credits (describe_sources)
};

/// The logical name of the ring strip and of the star-field cube map's folder (its faces px.jpg ... nz.jpg).
inline constexpr const char* kRingName = "textures/saturn_ring.png";
inline constexpr const char* kSkyFolder = "textures/skybox";

/// Loads the planet maps (textures/earth.jpg, ...), the ring strip (kRingName) and the star-field faces
/// (kSkyFolder/px.jpg, ...) from `data`: a folder laid out like ../shared, else the data packages' files
/// (OpenUniverse's maps and its ring strip rings.jpg, whose luminance is the ring's opacity). Each one that is
/// missing, or all with `procedural`, is made from its procedural fallback instead (noise per body, a random
/// star field): the packages have no map of the Sun's surface (their sun.jpg is a glow sprite) and no star
/// field, so those stay procedural without ../shared. The note says which.
SolarAssets load_solar_assets(const DataPath& data, bool procedural = false);

/// \brief Which picture of the sequence, and how it is filtered.
struct SolarView {
    int width = 640, height = 480;
    int frame = 0;                   ///< 0 .. frames - 1
    int frames = 1;                  ///< the camera makes one turn around the Sun over the sequence
    bool filter_maps = true;         ///< false: planet maps and sky at full resolution (for comparison)
    float samples_per_pixel = 4.0f;  ///< filtering_samples() of the settings the job is rendered with
};

/// \brief Where a body lands in the image (for tests and the shimmer measurement).
struct BodyOnScreen {
    const char* name;
    Vec2 centre;  ///< image position (pixels, y down)
    float radius_pixels;
    float lod;      ///< the map level used
    bool in_front;  ///< in front of the camera
};

/// The camera of a frame: one turn around the Sun over the sequence, looking slightly down at it.
CameraSpec solar_camera(const SolarView& view);

/// Where body `i` is at a frame: its sphere's transform (rtlab::scene_transform of its centre, spin and
/// tilt, and radius), the same numbers a scene file gives as "translate", "rotate" and "scale".
struct BodyPlacement {
    Vec3 centre;
    Vec3 rotate_degrees;
    float radius;
};
BodyPlacement body_placement(std::size_t i, const SolarView& view);

/// The job for one frame: an emissive Sun with a point light inside it that it does not shadow, the planets
/// textured at the level their size on screen asks for, Saturn's rings as an annulus whose ring-image alpha
/// is its opacity, and the star field as the environment. Physical units are not used: the classic
/// convention (no fall-off with distance). Jittered 4 samples per pixel by default. Sets the levels of the
/// assets' textures. `on_screen`, when given, receives every body's place in the image.
RenderJob make_solar_job(const SolarAssets& assets, const SolarView& view,
                         std::vector<BodyOnScreen>* on_screen = nullptr);

}  // namespace rtlab::solar
