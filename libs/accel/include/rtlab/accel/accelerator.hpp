#pragma once
/// \brief The one interface every acceleration structure over a triangle mesh offers, and the factory
/// that builds one by name ("kd-sah", "bvh", "embree", ...).
#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// \brief Closest hit on a mesh: t, triangle index and barycentrics (point = (1-u-v) p0 + u p1 + v p2).
struct MeshHit {
    float t = kInfinity;
    std::uint32_t primitive = 0xFFFFFFFFu;
    float u = 0.0f;
    float v = 0.0f;
    bool hit() const { return primitive != 0xFFFFFFFFu; }
};

/// \brief Size and shape of a built structure; fields that do not apply stay at -1.
struct AccelStats {
    double build_seconds = 0.0;
    std::int64_t nodes = -1;
    std::int64_t leaves = -1;
    std::int64_t empty_leaves = -1;
    std::int64_t max_depth = -1;
    double mean_leaf_primitives = -1.0;  ///< over non-empty leaves
    std::int64_t bytes = -1;             ///< nodes + primitive index arrays + per-primitive precomputation
    std::int64_t build_peak_bytes = -1;  ///< most the build held at once (Embree: its memory monitor's count)
    double sah_cost = -1.0;              ///< expected cost by the structure's own cost model
    std::int64_t leaf_width = -1;        ///< triangles a leaf tests at once (kd-trees over a mesh)
    /// What the builder would tell a user (the library writes nothing to a stream itself): for example
    /// that kd-sah-naive was asked for on a mesh it takes very long on. Empty when all went as expected.
    std::vector<std::string> warnings;
};

/// \brief Options common to all builders (each builder reads what applies to it).
struct BuildOptions {
    TriangleTest triangle_test = TriangleTest::watertight;
    int threads = 0;  ///< 0: oneTBB's default
    /// Triangles a kd-tree leaf tests at once: 4, 8 (AVX2) or 0 for the widest this CPU runs. Every width
    /// gives the same answers; kd_leaf_widths() lists those the CPU runs.
    int leaf_width = 0;
};

/// \brief An acceleration structure over one triangle mesh (which must outlive it).
class TriangleAccelerator {
public:
    virtual ~TriangleAccelerator() = default;
    /// The method name it was built with ("kd-sah").
    virtual std::string_view name() const = 0;
    /// Closest hit with ray.tmin < t < ray.tmax; fills hit and returns true on a hit.
    virtual bool intersect(const Ray& ray, MeshHit& hit) const = 0;
    /// Any hit with ray.tmin < t < ray.tmax; stops at the first blocker.
    virtual bool occluded(const Ray& ray) const = 0;
    /// Closest hits of a batch of rays, hits[i] answering rays[i] (MeshHit{} for a miss): each answer is
    /// intersect()'s for that ray alone, bit for bit. Structures that trace coherent rays together (camera
    /// rays, shadow rays towards one point: give them as 4 x 2 pixel tiles) override it; the default traces
    /// them one by one. hits.size() must be at least rays.size().
    virtual void intersect_packet(std::span<const Ray> rays, std::span<MeshHit> hits) const;
    /// occluded() of each ray (1 or 0 in blocked[i]), as intersect_packet.
    virtual void occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const;
    virtual AccelStats stats() const = 0;
};

/// Every method name the factory knows, in a stable order ("embree" only when built with Embree): the one list
/// of accelerator names (the kd-tree ones come from kKdStrategies), what a scene's mesh `accel` and the apps'
/// options allow.
std::vector<std::string> accelerator_methods();

/// Builds the named structure. Unknown names throw rtlab::Error listing the known ones.
std::unique_ptr<TriangleAccelerator> make_accelerator(std::string_view method, const TriangleMesh& mesh,
                                                      const BuildOptions& options = {});

}  // namespace rtlab
