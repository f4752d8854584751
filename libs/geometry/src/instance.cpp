#include <rtlab/core/box_ray.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/instance.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

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

    // The guard (misses_bounds()). A hit at t of the object-space ray o' + t d' is a point q of the inner shape's
    // bounds; the world ray's point o + t d lies off M q by the rounding of M^-1 o and M^-1 d and the inverse's
    // residual carried through M: at most about kappa (8 u + |R|) (|o| + t |d|) in max norm (kappa the product of
    // the two linear parts' norms), where t |d| <= |o| + |M q|. Taken four times over, the world box corners'
    // own rounding and the translation's included.
    const auto row_sum_max = [](const Mat3& abs_m) {
        float best = 0.0f;
        for (int r = 0; r < 3; ++r) best = std::max(best, abs_m[0][r] + abs_m[1][r] + abs_m[2][r]);
        return best;
    };
    const auto max_of = [](const Vec3& v) { return std::max({v.x, v.y, v.z}); };
    const float u = std::numeric_limits<float>::epsilon() * 0.5f;
    const float linear = row_sum_max(m_abs_linear);
    const float kappa = std::max(1.0f, linear * row_sum_max(m_abs_inverse_linear));
    m_guard_relative = 4.0f * kappa * (16.0f * u + row_sum_max(m_abs_residual_linear));
    const AABB inner = m_shape->bounds();
    m_world_bounds = bounds();
    const float extent = std::max(max_of(glm::abs(m_world_bounds.lo)), max_of(glm::abs(m_world_bounds.hi)));
    m_guard_absolute = m_guard_relative * (extent + max_of(m_abs_translation)) +
                       4.0f * linear * max_of(m_abs_residual_translation) + 4.0f * gamma_bound(4) * extent;
    m_guard = is_finite(inner.lo) && is_finite(inner.hi) && !inner.is_empty() && std::isfinite(extent) &&
              m_guard_relative < 1e-3f && std::isfinite(m_guard_absolute);
}

bool Instance::misses_bounds(const Ray& ray) const {
    if (!m_guard) return false;
    const Vec3 o = glm::abs(ray.origin);
    const float pad = m_guard_absolute + m_guard_relative * 2.0f * std::max({o.x, o.y, o.z});
    if (!(pad < kInfinity)) return false;  // NaN or infinite origins go the general way
    const AABB box{m_world_bounds.lo - Vec3(pad), m_world_bounds.hi + Vec3(pad)};
    float t0, t1;
    return !BoxRay(ray).clip(box, ray.tmax, t0, t1);
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
    if (misses_bounds(ray)) return false;
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

bool Instance::occluded(const Ray& ray) const { return !misses_bounds(ray) && m_shape->occluded(to_object(ray)); }

std::optional<UvFootprint> Instance::uv_footprint(const Mat4& to_world) const {
    // The identity is the common case (an instance in world space): its product with m_to_world would be
    // m_to_world, but for the sign of a zero.
    return m_shape->uv_footprint(to_world == Mat4(1.0f) ? m_to_world : to_world * m_to_world);
}

}  // namespace rtlab
