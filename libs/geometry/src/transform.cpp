#include <rtlab/geometry/transform.hpp>

#include <glm/gtc/matrix_transform.hpp>

namespace rtlab {

Mat4 scene_transform(const Vec3& translate, const Vec3& rotate_degrees, const Vec3& scale) {
    const Mat4 r = glm::rotate(Mat4(1.0f), glm::radians(rotate_degrees.z), Vec3(0, 0, 1)) *
                   glm::rotate(Mat4(1.0f), glm::radians(rotate_degrees.y), Vec3(0, 1, 0)) *
                   glm::rotate(Mat4(1.0f), glm::radians(rotate_degrees.x), Vec3(1, 0, 0));
    return glm::translate(Mat4(1.0f), translate) * r * glm::scale(Mat4(1.0f), scale);
}

}  // namespace rtlab
