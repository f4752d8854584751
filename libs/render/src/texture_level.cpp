#include <rtlab/render/pixel_sampler.hpp>
#include <rtlab/render/texture_level.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

namespace {

float tan_half_fov(const CameraSpec& camera) { return std::tan(0.5f * camera.vertical_fov_degrees * kPi / 180.0f); }

// n samples in a pixel average like a footprint sqrt(n) times smaller: half a level less per doubling.
float sample_bias(float samples) { return -0.5f * std::log2(std::max(1.0f, samples)); }

}  // namespace

float filtering_samples(const RenderSettings& settings) {
    if (settings.pattern == PixelPattern::adaptive) return 4.0f;
    return static_cast<float>(pattern_sample_count(settings.pattern, settings.spp));
}

float surface_texture_lod(const CameraSpec& camera, const UvFootprint& footprint, int texels_u, float samples) {
    const float d = glm::length(footprint.centre - camera.eye), r = footprint.radius;
    if (!(d > r) || !(footprint.u_length > 0.0f) || texels_u < 1) return 0.0f;
    const float pixels_per_tan = 0.5f * static_cast<float>(camera.height) / tan_half_fov(camera);
    const float pixels_per_unit = pixels_per_tan / std::sqrt(d * d - r * r);
    const float texels_per_pixel = static_cast<float>(texels_u) / (footprint.u_length * pixels_per_unit);
    const float lod = std::max(0.0f, std::log2(texels_per_pixel)) + sample_bias(samples);
    return std::isfinite(lod) ? std::max(0.0f, lod) : 0.0f;
}

float environment_texture_lod(const CameraSpec& camera, int face_texels, float samples) {
    // A face spans tan = -1..1, face_texels / 2 texels per unit of tan; the image height spans 2 tan_half.
    const float texels_per_pixel =
        static_cast<float>(face_texels) * tan_half_fov(camera) / static_cast<float>(camera.height);
    const float lod = std::max(0.0f, std::log2(texels_per_pixel)) + sample_bias(samples);
    return std::isfinite(lod) ? std::max(0.0f, lod) : 0.0f;
}

}  // namespace rtlab
