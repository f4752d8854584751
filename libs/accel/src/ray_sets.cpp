// The standard ray sets of FORMATS.md, computed exactly as specified there, in float.
#include <rtlab/accel/ray_io.hpp>
#include <rtlab/core/error.hpp>

#include <cmath>
#include <random>

namespace rtlab {

std::vector<Ray> primary_rays(const AABB& bounds, int n) {
    if (n <= 0 || bounds.is_empty()) throw Error("primary rays need a positive size and a non-empty box");
    const Point3 c = (bounds.lo + bounds.hi) / 2.0f;
    const float diag = glm::length(bounds.hi - bounds.lo);
    const Point3 eye = c + Vec3(0.0f, 0.0f, 1.5f * diag);
    const float th = std::tan(22.5f * kPi / 180.0f);
    const auto nf = static_cast<float>(n);
    std::vector<Ray> rays;
    rays.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const float px = (2.0f * (static_cast<float>(i) + 0.5f) / nf - 1.0f) * th;
            const float py = (1.0f - 2.0f * (static_cast<float>(j) + 0.5f) / nf) * th;
            rays.push_back(Ray{eye, glm::normalize(Vec3(px, py, -1.0f)), 0.0f, kInfinity});
        }
    }
    return rays;
}

std::vector<Ray> random_rays(const AABB& bounds, std::size_t count, std::uint32_t seed) {
    if (bounds.is_empty()) throw Error("random rays need a non-empty box");
    const Point3 c = (bounds.lo + bounds.hi) / 2.0f;
    const Vec3 extent = bounds.hi - bounds.lo;
    const float diag = glm::length(extent);
    const float radius = 1.5f * diag / 2.0f;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<Ray> rays;
    rays.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const float u1 = uniform(rng);
        const float u2 = uniform(rng);
        const float z = 1.0f - 2.0f * u1;
        const float phi = 2.0f * kPi * u2;
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const Point3 o = c + radius * Vec3(r * std::cos(phi), r * std::sin(phi), z);
        const float a = uniform(rng);
        const float b = uniform(rng);
        const float e = uniform(rng);
        const Point3 q = bounds.lo + Vec3(a * extent.x, b * extent.y, e * extent.z);
        rays.push_back(Ray{o, glm::normalize(q - o), 0.0f, kInfinity});
    }
    return rays;
}

}  // namespace rtlab
