#include <rtlab/core/error.hpp>
#include <rtlab/geometry/fit_on_floor.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace rtlab {

float fit_scale(const AABB& box, float size) {
    const Vec3 extent = box.hi - box.lo;
    const float largest = std::max({extent.x, extent.y, extent.z});
    if (!(largest > 0.0f) || !std::isfinite(largest))
        throw Error("fit: the model's bounds are empty or not finite (extent " + std::to_string(largest) + ")");
    if (!(size > 0.0f) || !std::isfinite(size)) throw Error("fit: the size must be > 0, not " + std::to_string(size));
    return size / largest;
}

Mat4 fit_on_floor(const AABB& box, float size) {
    const float scale = fit_scale(box, size);
    const Vec3 base(0.5f * (box.lo.x + box.hi.x), box.lo.y, 0.5f * (box.lo.z + box.hi.z));
    return glm::scale(Mat4(1.0f), Vec3(scale)) * glm::translate(Mat4(1.0f), -base);
}

}  // namespace rtlab
