#include <rtlab/core/error.hpp>
#include <rtlab/geometry/instance.hpp>

#include <cmath>

namespace rtlab {

Instance::Instance(std::shared_ptr<const Shape> shape, const Mat4& object_to_world)
    : m_shape(std::move(shape)), m_to_world(object_to_world) {
    if (!m_shape) throw Error("instance: no shape");
    const float det = glm::determinant(Mat3(object_to_world));
    if (!(std::abs(det) > 0.0f) || !std::isfinite(det))
        throw Error("instance: the transform is singular or not finite");
    m_to_object = glm::inverse(object_to_world);
    m_normal_to_world = glm::transpose(Mat3(m_to_object));
    const glm::dmat4 residual = glm::dmat4(m_to_object) * glm::dmat4(m_to_world) - glm::dmat4(1.0);
    for (int c = 0; c < 3; ++c) {
        m_abs_linear[c] = glm::abs(Vec3(m_to_world[c]));
        m_abs_inverse_linear[c] = glm::abs(Vec3(m_to_object[c]));
        m_abs_residual_linear[c] = Vec3(glm::abs(glm::dvec3(residual[c])));
    }
    m_abs_translation = glm::abs(Vec3(m_to_world[3]));
    m_abs_inverse_translation = glm::abs(Vec3(m_to_object[3]));
    m_abs_residual_translation = Vec3(glm::abs(glm::dvec3(residual[3])));
}

AABB Instance::bounds() const {
    const AABB b = m_shape->bounds();
    AABB out;
    for (int c = 0; c < 8; ++c) {
        const Point3 corner((c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y, (c & 4) ? b.hi.z : b.lo.z);
        out.expand(Point3(m_to_world * Vec4(corner, 1.0f)));
    }
    return out;
}

Ray Instance::to_object(const Ray& ray) const {
    return Ray{Point3(m_to_object * Vec4(ray.origin, 1.0f)), Vec3(m_to_object * Vec4(ray.direction, 0.0f)), ray.tmin,
               ray.tmax};
}

bool Instance::intersect(const Ray& ray, SurfaceHit& hit) const {
    SurfaceHit local = hit;
    if (!m_shape->intersect(to_object(ray), local)) return false;
    finish_hit(ray, local, hit);
    return true;
}

void Instance::finish_hit(const Ray& ray, const SurfaceHit& local, SurfaceHit& hit) const {
    hit = local;
    hit.point = Point3(m_to_world * Vec4(local.point, 1.0f));
    // The inner bound through the matrix, plus the rounding of this transform (Pharr et al., gamma(3)), plus
    // what a ray spawned here meets on its way back to object space: the rounding of the inverse transform
    // and the float inverse's residual, both measured in object space and taken to the world.
    const Vec3 q = glm::abs(local.point);
    const Vec3 back = gamma_bound(3) * (m_abs_inverse_linear * glm::abs(hit.point) + m_abs_inverse_translation) +
                      m_abs_residual_linear * q + m_abs_residual_translation;
    hit.point_error = gamma_bound(3) * (m_abs_linear * q + m_abs_translation) +
                      m_abs_linear * ((1.0f + gamma_bound(3)) * local.point_error + back);
    hit.geometric_normal = glm::normalize(m_normal_to_world * local.geometric_normal);
    hit.shading_normal = glm::normalize(m_normal_to_world * local.shading_normal);
    const Vec3 t = Vec3(m_to_world * Vec4(local.tangent, 0.0f));
    const Vec3 ortho = t - glm::dot(t, hit.shading_normal) * hit.shading_normal;
    if (glm::dot(ortho, ortho) > 0.0f) hit.tangent = glm::normalize(ortho);
    hit.front_face = glm::dot(ray.direction, hit.geometric_normal) < 0.0f;
    hit.shape = this;
}

bool Instance::occluded(const Ray& ray) const { return m_shape->occluded(to_object(ray)); }

std::optional<UvFootprint> Instance::uv_footprint(const Mat4& to_world) const {
    // The identity is the common case (an instance in world space): its product with m_to_world would be
    // m_to_world, but for the sign of a zero.
    return m_shape->uv_footprint(to_world == Mat4(1.0f) ? m_to_world : to_world * m_to_world);
}

}  // namespace rtlab
