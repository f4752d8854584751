#include <rtlab/core/error.hpp>
#include <rtlab/shading/environment_map.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rtlab {

namespace {

constexpr double kPiD = std::numbers::pi;

// Negative texels (a resampled map's ringing) read as 0; a texel that is not finite is an error.
void check_texels(Image& image, const std::string& what) {
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            RGB& c = image.at(x, y);
            if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
                throw Error(what + ": texel (" + std::to_string(x) + ", " + std::to_string(y) + ") is not finite");
            c = RGB(std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f));
        }
}

// The texels a bilinear lookup blends inside half-texel cell i of n texels (cells 2n): cell 2k lies between the
// centres of texels k - 1 and k, cell 2k + 1 between those of k and k + 1. Indices may be -1 or n (the caller
// wraps or clamps them).
std::pair<int, int> blended_texels(int i) {
    const int k = i / 2;
    return i % 2 == 0 ? std::pair{k - 1, k} : std::pair{k, k + 1};
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

// The solid angle of the rectangle [0, a] x [0, b] of a cube face at distance 1 (signed; a, b in [-1, 1]): a
// texel's is the sum of its corners' with alternating signs.
double face_solid_angle(double a, double b) { return std::atan2(a * b, std::sqrt(a * a + b * b + 1.0)); }

}  // namespace

struct EnvironmentMap::Data {
    Image equirectangular;                 // when not a cube
    std::shared_ptr<CubeMapTexture> cube;  // when a cube
    Distribution2D distribution;
    RGB integral;  // of the radiance over the sphere, without the intensity
};

namespace {

void check_options(const EnvironmentMapOptions& o) {
    if (!std::isfinite(o.rotation_degrees)) throw Error("environment map: the rotation is not finite");
    for (float c : {o.intensity.r, o.intensity.g, o.intensity.b})
        if (!(c >= 0.0f) || !std::isfinite(c)) throw Error("environment map: the intensity must be finite and >= 0");
    if (!(o.scene_radius > 0.0f) || !std::isfinite(o.scene_radius))
        throw Error("environment map: the scene radius must be finite and > 0");
}

}  // namespace

std::shared_ptr<const EnvironmentMap::Data> EnvironmentMap::build(Image image) {
    if (image.empty()) throw Error("environment map: the image is empty");
    check_texels(image, "environment map");
    auto data = std::make_shared<Data>();
    const int w = image.width(), h = image.height();
    // Weights on 2w x 2h half-texel cells: the largest luminance the bilinear lookup blends in the cell (u wraps,
    // v clamps at the poles), times sin(theta) at the cell's centre, the solid angle a row of cells covers.
    std::vector<float> weights(static_cast<std::size_t>(4) * w * h);
    for (int j = 0; j < 2 * h; ++j) {
        const auto [r0, r1] = blended_texels(j);
        const int rows[2] = {std::clamp(r0, 0, h - 1), std::clamp(r1, 0, h - 1)};
        const double sin_theta = std::sin(kPiD * (j + 0.5) / (2.0 * h));
        for (int i = 0; i < 2 * w; ++i) {
            const auto [c0, c1] = blended_texels(i);
            const int cols[2] = {wrap(c0, w), wrap(c1, w)};
            float largest = 0.0f;
            for (int r : rows)
                for (int c : cols) largest = std::max(largest, image.at(c, r).luminance());
            weights[static_cast<std::size_t>(j) * 2 * w + i] = static_cast<float>(largest * sin_theta);
        }
    }
    data->distribution = Distribution2D(weights, 2 * static_cast<std::size_t>(w), 2 * static_cast<std::size_t>(h));
    // Texel by texel: a row between polar angles theta0 and theta1 covers 2 pi (cos theta0 - cos theta1) / w each.
    double sum[3] = {0.0, 0.0, 0.0};
    for (int y = 0; y < h; ++y) {
        const double solid = 2.0 * kPiD / w * (std::cos(kPiD * y / h) - std::cos(kPiD * (y + 1) / h));
        for (int x = 0; x < w; ++x) {
            const RGB& c = image.at(x, y);
            sum[0] += c.r * solid, sum[1] += c.g * solid, sum[2] += c.b * solid;
        }
    }
    data->integral = RGB(static_cast<float>(sum[0]), static_cast<float>(sum[1]), static_cast<float>(sum[2]));
    data->equirectangular = std::move(image);
    return data;
}

std::shared_ptr<const EnvironmentMap::Data> EnvironmentMap::build(std::array<Image, 6> faces) {
    static constexpr const char* kNames[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (int f = 0; f < 6; ++f) check_texels(faces[f], std::string("environment cube map face '") + kNames[f] + "'");
    auto data = std::make_shared<Data>();
    data->cube = std::make_shared<CubeMapTexture>(std::move(faces));
    const CubeMapTexture& cube = *data->cube;
    const int n = cube.face_size();
    // Per face 2n x 2n half-texel cells (texels beyond an edge read from the neighbouring face, as the lookup
    // does), weighted by the face's Jacobian at the cell's centre; the faces stacked down the table.
    const std::size_t side = 2 * static_cast<std::size_t>(n);
    std::vector<float> weights(side * side * 6);
    double sum[3] = {0.0, 0.0, 0.0};
    for (int f = 0; f < 6; ++f) {
        const auto face = static_cast<CubeFace>(f);
        for (int j = 0; j < 2 * n; ++j) {
            const auto [r0, r1] = blended_texels(j);
            const double tc = 2.0 * (j + 0.5) / (2.0 * n) - 1.0;
            for (int i = 0; i < 2 * n; ++i) {
                const auto [c0, c1] = blended_texels(i);
                const double sc = 2.0 * (i + 0.5) / (2.0 * n) - 1.0;
                const double jacobian = 4.0 / std::pow(1.0 + sc * sc + tc * tc, 1.5);
                float largest = 0.0f;
                for (int r : {r0, r1})
                    for (int c : {c0, c1}) largest = std::max(largest, cube.texel(face, c, r).luminance());
                weights[(static_cast<std::size_t>(f) * side + j) * side + i] = static_cast<float>(largest * jacobian);
            }
        }
        for (int y = 0; y < n; ++y) {
            const double t0 = 2.0 * y / n - 1.0, t1 = 2.0 * (y + 1) / n - 1.0;
            for (int x = 0; x < n; ++x) {
                const double s0 = 2.0 * x / n - 1.0, s1 = 2.0 * (x + 1) / n - 1.0;
                const double solid = face_solid_angle(s1, t1) - face_solid_angle(s0, t1) - face_solid_angle(s1, t0) +
                                     face_solid_angle(s0, t0);
                const RGB& c = cube.face(face).at(x, y);
                sum[0] += c.r * solid, sum[1] += c.g * solid, sum[2] += c.b * solid;
            }
        }
    }
    data->distribution = Distribution2D(weights, side, 6 * side);
    data->integral = RGB(static_cast<float>(sum[0]), static_cast<float>(sum[1]), static_cast<float>(sum[2]));
    return data;
}

EnvironmentMap::EnvironmentMap(Image equirectangular, const EnvironmentMapOptions& options)
    : EnvironmentMap(build(std::move(equirectangular)), options) {}

EnvironmentMap::EnvironmentMap(std::array<Image, 6> faces, const EnvironmentMapOptions& options)
    : EnvironmentMap(build(std::move(faces)), options) {}

EnvironmentMap::EnvironmentMap(std::shared_ptr<const Data> data, const EnvironmentMapOptions& options)
    : m_data(std::move(data)), m_options(options) {
    check_options(options);
    const double angle = static_cast<double>(options.rotation_degrees) * kPiD / 180.0;
    m_cos = static_cast<float>(std::cos(angle));
    m_sin = static_cast<float>(std::sin(angle));
}

bool EnvironmentMap::is_cube() const { return m_data->cube != nullptr; }
const Distribution2D& EnvironmentMap::distribution() const { return m_data->distribution; }

// The map turned by the right-hand rule about +y: local +x (the centre column) goes to (cos a, 0, -sin a).
Vec3 EnvironmentMap::to_world(const Vec3& l) const {
    return {m_cos * l.x + m_sin * l.z, l.y, m_cos * l.z - m_sin * l.x};
}
Vec3 EnvironmentMap::to_local(const Vec3& w) const {
    return {m_cos * w.x - m_sin * w.z, w.y, m_sin * w.x + m_cos * w.z};
}

RGB EnvironmentMap::lookup(const Vec3& d) const {
    if (m_data->cube) return m_data->cube->sample(d);
    const Image& img = m_data->equirectangular;
    const int w = img.width(), h = img.height();
    const float u = 0.5f + std::atan2(d.z, d.x) * (0.5f / kPi);
    const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) * kInvPi;
    // Texel centres at integers: column x's centre at u = (x + 0.5) / w.
    const float x = u * static_cast<float>(w) - 0.5f, y = v * static_cast<float>(h) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    const int c0 = wrap(ix, w), c1 = wrap(ix + 1, w);
    const int r0 = std::clamp(iy, 0, h - 1), r1 = std::clamp(iy + 1, 0, h - 1);
    const RGB top = lerp(img.at(c0, r0), img.at(c1, r0), fx);
    const RGB bottom = lerp(img.at(c0, r1), img.at(c1, r1), fx);
    return lerp(top, bottom, fy);
}

RGB EnvironmentMap::radiance(const Vec3& direction) const {
    const float len = glm::length(direction);
    if (!(len > 0.0f) || !std::isfinite(len)) return {};
    return lookup(to_local(direction / len)) * m_options.intensity;
}

float EnvironmentMap::pdf_local(const Vec3& d) const {
    const Distribution2D& dist = m_data->distribution;
    const std::size_t nu = dist.columns(), nv = dist.rows();
    auto cell = [](float x, std::size_t n) {
        return std::min(n - 1, static_cast<std::size_t>(std::max(0.0f, x) * static_cast<float>(n)));
    };
    if (m_data->cube) {
        const CubeFaceCoord c = cube_face_coord(d);
        const std::size_t side = nu;
        const std::size_t row = static_cast<std::size_t>(c.face) * side + cell(c.t, side);
        const float sc = 2.0f * c.s - 1.0f, tc = 2.0f * c.t - 1.0f;
        const float q = 1.0f + sc * sc + tc * tc;
        return dist.pdf_of(cell(c.s, side), row) * q * std::sqrt(q) / 24.0f;
    }
    const float sin_theta = std::sqrt(std::max(0.0f, d.x * d.x + d.z * d.z));
    if (!(sin_theta > 0.0f)) return 0.0f;
    const float u = 0.5f + std::atan2(d.z, d.x) * (0.5f / kPi);
    const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) * kInvPi;
    return dist.pdf_of(cell(u, nu), cell(v, nv)) / (2.0f * kPi * kPi * sin_theta);
}

std::optional<EmitterSample> EnvironmentMap::sample_li(const Point3& p, const Vec2& u) const {
    const Distribution2D::Sample s = m_data->distribution.sample(u);
    Vec3 local;
    float pdf = 0.0f;
    if (m_data->cube) {
        const std::size_t side = m_data->distribution.columns();
        const auto face = static_cast<CubeFace>(s.row / side);
        const float t = std::clamp(s.uv.y * 6.0f - static_cast<float>(s.row / side), 0.0f, 0x1.fffffep-1f);
        local = glm::normalize(cube_face_direction(face, s.uv.x, t));
        const float sc = 2.0f * s.uv.x - 1.0f, tc = 2.0f * t - 1.0f;
        const float q = 1.0f + sc * sc + tc * tc;
        pdf = s.pdf * q * std::sqrt(q) / 24.0f;
    } else {
        const float theta = kPi * s.uv.y, phi = 2.0f * kPi * (s.uv.x - 0.5f);
        const float sin_theta = std::sin(theta);
        if (!(sin_theta > 0.0f)) return std::nullopt;
        local = Vec3(sin_theta * std::cos(phi), std::cos(theta), sin_theta * std::sin(phi));
        pdf = s.pdf / (2.0f * kPi * kPi * sin_theta);
    }
    if (!(pdf > 0.0f) || !std::isfinite(pdf)) return std::nullopt;
    EmitterSample out;
    out.wi = glm::normalize(to_world(local));
    out.position = p + out.wi;
    out.at_infinity = true;
    out.radiance = lookup(local) * m_options.intensity;
    out.pdf = pdf;
    return out;
}

float EnvironmentMap::pdf_li(const Point3&, const Vec3& wi, const Point3&, const Normal3&) const {
    const float len = glm::length(wi);
    if (!(len > 0.0f) || !std::isfinite(len)) return 0.0f;
    return pdf_local(to_local(wi / len));
}

RGB EnvironmentMap::radiance_integral() const { return m_data->integral * m_options.intensity; }

RGB EnvironmentMap::power() const {
    return radiance_integral() * (kPi * m_options.scene_radius * m_options.scene_radius);
}

std::shared_ptr<const EnvironmentEmitter> EnvironmentMap::for_scene_radius(float scene_radius) const {
    EnvironmentMapOptions o = m_options;
    o.scene_radius = scene_radius;
    return std::shared_ptr<const EnvironmentMap>(new EnvironmentMap(m_data, o));
}

}  // namespace rtlab
