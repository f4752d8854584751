// Texture "cubemap": an environment (skybox) looked up by lookup.direction.
//
// Faces follow the OpenGL / Direct3D cube-map convention stated in rtlab/textures/cube_map.hpp (px nx
// py ny pz nz; face by the largest |component|; s along columns, t down the rows). Give either the six
// face files, one horizontal-cross file (4N x 3N: py above pz; nx pz px nz; ny below pz), or a folder
// holding px.<ext> ... nz.<ext>. Filtering is bilinear and seamless: texels beyond a face's edge are read
// from the neighbouring face, so there is no seam at any of the 12 edges.
//
// Parameters (exactly one of the three sources)
//   px nx py ny pz nz   the six face files
//   cross               one horizontal-cross file
//   folder              a folder with px.<extension> ... nz.<extension>
//   extension           file extension used with folder                 default "jpg"
//   encoding            srgb | linear: how 8-bit files are decoded      default srgb
//   intensity           multiplier on the looked-up colour, >= 0        default 1
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/textures/cube_map.hpp>
#include <rtlab/textures/mip_map.hpp>

#include "texture_params.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace rtlab {

namespace {
constexpr const char* kFaceNames[6] = {"px", "nx", "py", "ny", "pz", "nz"};

// Where each face sits in the horizontal cross, in face-size units (column, row).
constexpr int kCrossCell[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
}  // namespace

CubeMapTexture::CubeMapTexture(std::array<Image, 6> faces) : m_faces(std::move(faces)) {
    m_size = m_faces[0].width();
    for (int f = 0; f < 6; ++f) {
        const Image& img = m_faces[f];
        const std::string size = std::to_string(img.width()) + "x" + std::to_string(img.height());
        if (img.empty()) throw Error(std::string("cube map face '") + kFaceNames[f] + "' is empty");
        if (img.width() != img.height())
            throw Error(std::string("cube map face '") + kFaceNames[f] + "' is " + size + ", not square");
        if (img.width() != m_size)
            throw Error(std::string("cube map face '") + kFaceNames[f] + "' is " + size + " but face 'px' is " +
                        std::to_string(m_size) + "x" + std::to_string(m_size) + "; all faces must be the same size");
    }
}

std::shared_ptr<CubeMapTexture> CubeMapTexture::from_cross(const Image& cross) {
    const int n = cross.width() / 4;
    if (cross.empty() || cross.width() != 4 * n || cross.height() != 3 * n)
        throw Error("cube map cross image is " + std::to_string(cross.width()) + "x" + std::to_string(cross.height()) +
                    ", not 4N x 3N (a horizontal cross)");
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) {
        faces[f] = Image(n, n);
        const int x0 = kCrossCell[f][0] * n, y0 = kCrossCell[f][1] * n;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) faces[f].at(x, y) = cross.at(x0 + x, y0 + y);
    }
    return std::make_shared<CubeMapTexture>(std::move(faces));
}

std::shared_ptr<CubeMapTexture> CubeMapTexture::load_faces(const std::array<std::filesystem::path, 6>& paths,
                                                           ColorEncoding encoding) {
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) faces[f] = read_image(paths[f], encoding);
    try {
        return std::make_shared<CubeMapTexture>(std::move(faces));
    } catch (const Error& e) {
        // Name the files: "face 'ny'" alone does not say which file is wrong.
        std::string files;
        for (int f = 0; f < 6; ++f)
            files += std::string(f ? ", " : "") + kFaceNames[f] + " = '" + paths[f].string() + "'";
        throw Error(std::string(e.what()) + " (files " + files + ")");
    }
}

std::shared_ptr<CubeMapTexture> CubeMapTexture::load_cross(const std::filesystem::path& path, ColorEncoding encoding) {
    const Image cross = read_image(path, encoding);
    try {
        return from_cross(cross);
    } catch (const Error& e) {
        throw Error(file_error_message(path, e.what()));
    }
}

RGB CubeMapTexture::texel(CubeFace face, int x, int y) const {
    const int n = m_size;
    const bool in_x = x >= 0 && x < n, in_y = y >= 0 && y < n;
    if (in_x && in_y) return m_faces[static_cast<int>(face)].at(x, y);
    const int cx = std::clamp(x, 0, n - 1), cy = std::clamp(y, 0, n - 1);
    if (!in_x && !in_y) {
        // Beyond a cube corner, where only three faces meet: the mean of their three corner texels.
        return (texel(face, cx, cy) + texel(face, x, cy) + texel(face, cx, y)) * (1.0f / 3.0f);
    }
    // One texel beyond an edge: the neighbouring face's texel whose centre is nearest to this one's.
    const float s = (static_cast<float>(x) + 0.5f) / static_cast<float>(n);
    const float t = (static_cast<float>(y) + 0.5f) / static_cast<float>(n);
    const CubeFaceCoord c = cube_face_coord(cube_face_direction(face, s, t));
    const int nx = std::clamp(static_cast<int>(c.s * static_cast<float>(n)), 0, n - 1);
    const int ny = std::clamp(static_cast<int>(c.t * static_cast<float>(n)), 0, n - 1);
    return m_faces[static_cast<int>(c.face)].at(nx, ny);
}

RGB CubeMapTexture::sample(const Vec3& direction) const {
    if (!is_finite(direction) || direction == Vec3(0.0f)) return {};
    const CubeFaceCoord c = cube_face_coord(direction);
    const float n = static_cast<float>(m_size);
    const float x = c.s * n - 0.5f, y = c.t * n - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    const RGB top = lerp(texel(c.face, ix, iy), texel(c.face, ix + 1, iy), fx);
    const RGB bottom = lerp(texel(c.face, ix, iy + 1), texel(c.face, ix + 1, iy + 1), fx);
    return lerp(top, bottom, fy);
}

namespace detail {

namespace {
class ScaledTexture final : public Texture {
public:
    ScaledTexture(std::shared_ptr<const Texture> inner, float scale) : m_inner(std::move(inner)), m_scale(scale) {}
    RGB eval(const TextureLookup& q) const override { return m_inner->eval(q) * m_scale; }

private:
    std::shared_ptr<const Texture> m_inner;
    float m_scale;
};

// A cube map and its box-filtered levels (faces halved down to 1 texel), looked up between the two levels
// around its lod: a star field seen through a wide lens averages its stars instead of flickering.
class CubeMapLevels final : public Texture, public LevelOfDetail {
public:
    CubeMapLevels(std::array<Image, 6> faces, float intensity) : m_intensity(intensity) {
        while (true) {
            const bool last = faces[0].width() <= 1;
            std::array<Image, 6> next;
            if (!last)
                for (std::size_t f = 0; f < 6; ++f) next[f] = downsample(faces[f]);
            m_levels.push_back(std::make_shared<CubeMapTexture>(std::move(faces)));
            if (last) break;
            faces = std::move(next);
        }
        set_lod(0.0f);
    }
    RGB eval(const TextureLookup& q) const override {
        RGB c = m_levels[static_cast<std::size_t>(m_blend.first)]->eval(q);
        if (m_blend.blend > 0.0f)
            c = lerp(c, m_levels[static_cast<std::size_t>(m_blend.second)]->eval(q), m_blend.blend);
        return m_intensity == 1.0f ? c : c * m_intensity;
    }
    void set_lod(float lod) override {
        m_blend = level_blend(lod, static_cast<int>(m_levels.size()));
        m_lod = static_cast<float>(m_blend.first) + m_blend.blend;
    }
    float lod() const override { return m_lod; }
    int texels_u() const override { return m_levels.front()->face_size(); }

private:
    std::vector<std::shared_ptr<const CubeMapTexture>> m_levels;
    float m_intensity;
    float m_lod = 0.0f;
    LevelBlend m_blend;
};

std::array<Image, 6> faces_of(const CubeMapTexture& map) {
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) faces[f] = map.face(static_cast<CubeFace>(f));
    return faces;
}

TypeSpec cubemap_spec() {
    TypeSpec s(
        "environment cube map by lookup.direction, OpenGL face convention, seamless bilinear filtering; "
        "give exactly one of: the six faces, cross, folder or bake");
    for (const char* face : kFaceNames)
        s.add(face, ParamKind::file, std::string("the ") + face + " face (with the five others)");
    s.add("cross", ParamKind::file, "one horizontal-cross file (4N x 3N)");
    s.add("folder", ParamKind::folder, "a folder holding px.<extension> ... nz.<extension>");
    s.add("extension", ParamKind::text, "the face files' extension in folder").defaults("jpg").part_of_files();
    add_image_options(s, "the baked faces' width in texels, a whole number in 1..8192", "512");
    return s;
}

// bake_size: one whole number, given as a number or a list of one (a "numbers" parameter).
int bake_face_size(const Params& p) {
    const Params::List l = p.has("bake_size") ? p.get_list("bake_size") : Params::List{512.0};
    if (l.size() != 1 || !(l[0] >= 1.0 && l[0] <= 8192.0) || l[0] != std::floor(l[0]))
        fail_param(p, "bake_size", "must be a whole number in 1..8192");
    return static_cast<int>(l[0]);
}
}  // namespace

void register_cubemap(TextureRegistry& registry) {
    registry.add(
        "cubemap",
        [](const Params& p) -> std::shared_ptr<Texture> {
            int faces_given = 0;
            for (const char* name : kFaceNames) faces_given += p.has(name) ? 1 : 0;
            const int sources = (faces_given > 0 ? 1 : 0) + (p.has("cross") ? 1 : 0) + (p.has("folder") ? 1 : 0) +
                                (p.has("bake") ? 1 : 0);
            if (sources != 1)
                throw Error(p.context() +
                            ": give exactly one of the six faces (px nx py ny pz nz), 'cross', 'folder' or 'bake'");
            if (p.has("bake_size") && !p.has("bake")) fail_param(p, "bake_size", "is only used with 'bake'");
            if (p.has("extension") && !p.has("folder")) fail_param(p, "extension", "is only used with 'folder'");
            const ColorEncoding encoding = get_encoding(p);
            const float intensity = positive_float(p, "intensity", 1.0f, true);
            // Without "lod", no pyramid (a plain float: GCC 12 warns falsely on an optional here).
            const bool levelled = p.has("lod");
            const float lod = levelled ? float_in_range(p, "lod", 0.0f, 0.0f, 64.0f) : 0.0f;
            if (p.has("bake")) {
                const auto texture = p.get_object<Texture>("bake");
                if (!texture) fail_param(p, "bake", "must be a texture");
                const int size = bake_face_size(p);
                std::array<Image, 6> faces = bake_cube_faces(*texture, size);
                if (!levelled) {
                    auto map = std::make_shared<CubeMapTexture>(std::move(faces));
                    if (intensity == 1.0f) return map;
                    return std::make_shared<ScaledTexture>(map, intensity);
                }
                auto levels = std::make_shared<CubeMapLevels>(std::move(faces), intensity);
                levels->set_lod(lod);
                return levels;
            }
            std::array<std::filesystem::path, 6> paths;
            if (!p.has("cross")) {
                const bool use_folder = p.has("folder");
                const std::string folder = use_folder ? p.get_string("folder") : "";
                const std::string ext = p.get_string("extension", "jpg");
                for (int f = 0; f < 6; ++f) {
                    if (use_folder)
                        paths[f] = std::filesystem::path(folder) / (std::string(kFaceNames[f]) + "." + ext);
                    else if (p.has(kFaceNames[f]))
                        paths[f] = p.get_string(kFaceNames[f]);
                    else
                        fail_param(p, kFaceNames[f], "is missing: all six faces are needed");
                }
            }
            std::shared_ptr<CubeMapTexture> map;
            try {
                map = p.has("cross") ? CubeMapTexture::load_cross(p.get_string("cross"), encoding)
                                     : CubeMapTexture::load_faces(paths, encoding);
            } catch (const Error& e) {
                throw Error(p.context() + ": " + e.what());
            }
            if (levelled) {
                auto levels = std::make_shared<CubeMapLevels>(faces_of(*map), intensity);
                levels->set_lod(lod);
                return levels;
            }
            if (intensity == 1.0f) return map;
            return std::make_shared<ScaledTexture>(map, intensity);
        },
        cubemap_spec());
}

}  // namespace detail
}  // namespace rtlab
