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

void SceneQuery::intersect_surface_packet(std::span<const Ray> rays, std::span<SurfaceHit> hits,
                                          std::span<SurfaceInfo> infos, std::span<std::uint8_t> found) const {
    for (std::size_t i = 0; i < rays.size(); ++i) found[i] = intersect_surface(rays[i], hits[i], infos[i]) ? 1 : 0;
}

void SceneQuery::occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
    for (std::size_t i = 0; i < rays.size(); ++i) blocked[i] = occluded(rays[i]) ? 1 : 0;
}

}  // namespace rtlab
