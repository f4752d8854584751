// The packet queries of structures that trace every ray alone.
#include <rtlab/accel/accelerator.hpp>

namespace rtlab {

void TriangleAccelerator::intersect_packet(std::span<const Ray> rays, std::span<MeshHit> hits) const {
    for (std::size_t i = 0; i < rays.size(); ++i) {
        MeshHit hit;
        hits[i] = intersect(rays[i], hit) ? hit : MeshHit{};
    }
}

void TriangleAccelerator::occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
    for (std::size_t i = 0; i < rays.size(); ++i) blocked[i] = occluded(rays[i]) ? 1 : 0;
}

}  // namespace rtlab
