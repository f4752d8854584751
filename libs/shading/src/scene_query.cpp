#include <rtlab/shading/scene_query.hpp>

namespace rtlab {

bool SceneQuery::intersect_surface(const Ray& ray, SurfaceHit& hit, SurfaceInfo& info) const {
    if (!intersect(ray, hit)) return false;
    info = surface(hit);
    return true;
}

ShadowHit SceneQuery::shadow(const Ray& ray, bool check_opaque, SurfaceHit& hit, SurfaceInfo& info) const {
    if (check_opaque && occluded(ray)) return ShadowHit::opaque;
    if (!intersect_transmissive(ray, hit)) return ShadowHit::clear;
    info = surface(hit);
    return ShadowHit::transmissive;
}

}  // namespace rtlab
