// Environment "envmap": light from an image all around the scene (rtlab/shading/environment_map.hpp), seen by
// rays that escape and, under direct and path, importance-sampled by luminance with multiple importance sampling.
//
// Files (exactly one source): `filename`, an equirectangular map (row 0 straight up; the centre column faces
// +x, u = 0 faces -x, u = 0.25 faces -z; unmirrored seen from inside); or a cube map, as six faces `px` ... `nz`
// or one horizontal `cross` (the faces and the cross of the cubemap texture). OpenEXR (any compression, DWAB
// included), Radiance HDR and PFM are linear; 8-bit files are decoded by `encoding`.
//
// Parameters
//   filename              equirectangular map
//   px nx py ny pz nz     cube faces
//   cross                 cube map as a horizontal cross (4N x 3N)
//   rotation              degrees about +y, right-handed (counter-clockwise seen from above)   default 0
//   intensity             colour multiplying the map                                             default 1
//   encoding              srgb | linear: how 8-bit files are decoded                             default srgb
#include <rtlab/core/error.hpp>
#include <rtlab/core/param_checks.hpp>
#include <rtlab/render/environment_types.hpp>
#include <rtlab/render/image_input.hpp>
#include <rtlab/shading/environment_map.hpp>

#include <array>
#include <string>

namespace rtlab {

namespace {

constexpr const char* kFaces[6] = {"px", "nx", "py", "ny", "pz", "nz"};
// Where each face sits in a horizontal cross, in face-size units (column, row): the cubemap texture's layout.
constexpr int kCrossCell[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};

TypeSpec envmap_spec() {
    TypeSpec s(
        "an environment map all around the scene, equirectangular or cube, importance-sampled by luminance (direct, "
        "path); the background of every integrator");
    s.add("filename", ParamKind::file,
          "an equirectangular map (EXR, HDR, PFM, PNG, JPG): row 0 up, centre column towards +x, u = 0 towards -x")
        .part_of_files();
    for (const char* face : kFaces)
        s.add(face, ParamKind::file, std::string("cube map face ") + face + " (all six, instead of filename)")
            .part_of_files();
    s.add("cross", ParamKind::file, "a cube map as one horizontal cross, 4N x 3N (instead of filename)")
        .part_of_files();
    s.add("rotation", ParamKind::number, "turns the map about +y, counter-clockwise seen from above")
        .defaults("0")
        .range(-360, 360)
        .in("degrees");
    s.add("intensity", ParamKind::colour, "multiplies the map").defaults("1");
    s.add("encoding", ParamKind::word, "how an 8-bit file's values are decoded")
        .defaults("srgb")
        .allow({"srgb", "linear"});
    return s;
}

// A file's image, its errors shown at the key that named it.
Image read_at(const Params& p, std::string_view key, ColorEncoding encoding) {
    const std::string file = p.get_string(key);
    try {
        return read_image_file(file, encoding);
    } catch (const Error& e) {
        fail_param(p, key, std::string("cannot be read: ") + e.what());
    }
}

std::shared_ptr<EnvironmentEmitter> make_envmap(const Params& p) {
    EnvironmentMapOptions o;
    o.rotation_degrees = float_in_range(p, "rotation", 0.0f, -360.0f, 360.0f);
    o.intensity = finite_rgb(p, "intensity", RGB(1.0f));
    if (o.intensity.r < 0.0f || o.intensity.g < 0.0f || o.intensity.b < 0.0f)
        fail_param(p, "intensity", "must be >= 0");
    const ColorEncoding encoding =
        one_of(p, "encoding", "srgb", {"srgb", "linear"}) == "srgb" ? ColorEncoding::srgb : ColorEncoding::linear;
    int faces = 0;
    for (const char* face : kFaces) faces += p.has(face) ? 1 : 0;
    const int sources = (p.has("filename") ? 1 : 0) + (faces > 0 ? 1 : 0) + (p.has("cross") ? 1 : 0);
    if (sources != 1)
        throw Error(p.context() +
                    ": give exactly one of 'filename' (equirectangular), the six faces 'px' ... 'nz', "
                    "or 'cross'");
    if (faces > 0 && faces < 6) {
        for (const char* face : kFaces)
            if (!p.has(face)) fail_param(p, face, "is missing: a cube map needs all six faces");
    }
    try {
        if (p.has("filename")) return std::make_shared<EnvironmentMap>(read_at(p, "filename", encoding), o);
        std::array<Image, 6> images;
        if (p.has("cross")) {
            const Image cross = read_at(p, "cross", encoding);
            const int n = cross.width() / 4;
            if (cross.width() != 4 * n || cross.height() != 3 * n || n == 0)
                fail_param(p, "cross",
                           "is " + std::to_string(cross.width()) + "x" + std::to_string(cross.height()) +
                               ", not 4N x 3N (a horizontal cross)");
            for (int f = 0; f < 6; ++f) {
                images[f] = Image(n, n);
                for (int y = 0; y < n; ++y)
                    for (int x = 0; x < n; ++x)
                        images[f].at(x, y) = cross.at(kCrossCell[f][0] * n + x, kCrossCell[f][1] * n + y);
            }
        } else {
            for (int f = 0; f < 6; ++f) images[f] = read_at(p, kFaces[f], encoding);
        }
        return std::make_shared<EnvironmentMap>(std::move(images), o);
    } catch (const ParamError&) {
        throw;
    } catch (const Error& e) {
        // A texel that is not finite, faces of unequal sizes: the map's problem, said with its files.
        std::string files;
        for (const char* key : {"filename", "cross", "px", "nx", "py", "ny", "pz", "nz"})
            if (p.has(key)) files += std::string(files.empty() ? "" : ", ") + "'" + p.get_string(key) + "'";
        throw Error(p.context() + ": " + e.what() + " (" + files + ")");
    }
}

}  // namespace

void register_builtins(EnvironmentRegistry& registry) { registry.add("envmap", make_envmap, envmap_spec()); }

EnvironmentRegistry make_environment_registry() {
    EnvironmentRegistry r("environment");
    register_builtins(r);
    return r;
}

}  // namespace rtlab
