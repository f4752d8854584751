#include <rtlab/geometry/skybox.hpp>

namespace rtlab {

std::optional<CubeFaceCoord> skybox_lookup(const Vec3& direction) {
    if (!is_finite(direction) || (direction.x == 0.0f && direction.y == 0.0f && direction.z == 0.0f))
        return std::nullopt;
    return cube_face_coord(direction);
}

}  // namespace rtlab
