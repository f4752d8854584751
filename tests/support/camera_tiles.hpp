#pragma once
// Camera rays in the renderer's coherent groups, for the packet tests of accel and render.
#include <rtlab/core/ray.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace rtlab::test {

/// n x n pinhole rays from `eye` towards `target` over a square field of `width` at the target, in 4 x 2
/// pixel tiles (rays 0-3 the tile's upper row, 4-7 its lower one), as the renderer's coherent entry point
/// would give them. n must be a multiple of 4.
inline std::vector<Ray> camera_tiles(const Point3& eye, const Point3& target, float width, int n,
                                     float tmax = kInfinity) {
    const Vec3 forward = target - eye;
    const Vec3 right = glm::normalize(
        glm::cross(forward, std::abs(forward.y) < std::abs(forward.x) || std::abs(forward.y) < std::abs(forward.z)
                                ? Vec3(0, 1, 0)
                                : Vec3(1, 0, 0)));
    const Vec3 up = glm::normalize(glm::cross(right, forward));
    std::vector<Ray> rays;
    for (int ty = 0; ty < n; ty += 2)
        for (int tx = 0; tx < n; tx += 4)
            for (int y = ty; y < ty + 2; ++y)
                for (int x = tx; x < tx + 4; ++x) {
                    const float sx = (static_cast<float>(x) + 0.5f) / static_cast<float>(n) - 0.5f;
                    const float sy = 0.5f - (static_cast<float>(y) + 0.5f) / static_cast<float>(n);
                    rays.push_back(Ray{eye, forward + width * (sx * right + sy * up), 0.0f, tmax});
                }
    return rays;
}

}  // namespace rtlab::test
