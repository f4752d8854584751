#pragma once
/// \brief The ray queries the Whitted recursion asks of a scene, and ShapeList, the plain brute-force answer.
#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/shape.hpp>
#include <rtlab/shading/material.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

namespace rtlab {

/// \brief Per-object flags beside the material.
struct SurfaceFlags {
    bool casts_shadows = true;  ///< false: invisible to shadow rays (the Sun sphere around a point light)
    bool reversed = false;      ///< inside and outside swapped (normals flipped)
};

/// \brief What the scene knows about the object a hit belongs to.
struct SurfaceInfo {
    const Material* material = nullptr;
    SurfaceFlags flags;
};

/// \brief What a shadow segment meets first (SceneQuery::shadow).
enum class ShadowHit { clear, opaque, transmissive };

/// \brief The scene as the shading library sees it; render implements it over its acceleration structures.
///
/// Shadow casters split in two: opaque ones (material->transmits_shadows() false) answer occluded(), the
/// transmissive ones (kt > 0 or opacity < 1) answer intersect_transmissive(). Objects that do not cast
/// shadows answer neither. Hits keep the SurfaceHit conventions: ray.tmin < t < ray.tmax.
class SceneQuery {
public:
    virtual ~SceneQuery() = default;
    /// Closest hit over every object.
    virtual bool intersect(const Ray& ray, SurfaceHit& hit) const = 0;
    /// Any hit over the opaque shadow casters.
    virtual bool occluded(const Ray& ray) const = 0;
    /// Closest hit over the transmissive shadow casters.
    virtual bool intersect_transmissive(const Ray& ray, SurfaceHit& hit) const = 0;
    /// The material and flags of the object hit.shape belongs to (hit.shape is the outermost shape).
    virtual SurfaceInfo surface(const SurfaceHit& hit) const = 0;

    /// intersect() and surface() in one query, for shading. The record may leave out the uv of an object
    /// whose material does not read_lookup(), and the tangent of one whose material does not
    /// reflects_direct_light() (nothing reads them there). The default runs the two queries.
    virtual bool intersect_surface(const Ray& ray, SurfaceHit& hit, SurfaceInfo& info) const;
    /// One query per shadow-ray segment: with check_opaque, `opaque` when occluded(); else the closest
    /// transmissive caster (intersect_transmissive(), uv and tangent left out as for intersect_surface()) with its
    /// info, or `clear`. The default runs the three queries.
    virtual ShadowHit shadow(const Ray& ray, bool check_opaque, SurfaceHit& hit, SurfaceInfo& info) const;

    /// intersect_surface() of each of a group of rays, for rays traced together (camera rays, shadow rays towards
    /// one point; best as 4 x 2 pixel tiles): found[i] = 1 and hits[i], infos[i] as intersect_surface(rays[i],
    /// hits[i], infos[i]) leaves them, bit for bit, else found[i] = 0 (hits[i] and infos[i] as that query leaves
    /// them on a miss). hits, infos and found hold at least rays.size() elements. The default asks one ray at a time.
    virtual void intersect_surface_packet(std::span<const Ray> rays, std::span<SurfaceHit> hits,
                                          std::span<SurfaceInfo> infos, std::span<std::uint8_t> found) const;
    /// occluded() of each ray: blocked[i] = 1 or 0, as intersect_surface_packet.
    virtual void occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const;
    /// Whether the packet queries trace any rays together; false (the default): they ask one ray at a time, so a
    /// caller may as well ask single queries.
    virtual bool traces_packets() const { return false; }
};

/// \brief Shapes with their materials, every query by brute force: tests, and the "plain list" scene level.
class ShapeList final : public SceneQuery {
public:
    /// Adds an object; a null shape or material is an rtlab::Error. Returns its index.
    std::size_t add(std::shared_ptr<const Shape> shape, std::shared_ptr<const Material> material,
                    SurfaceFlags flags = {});
    std::size_t size() const { return m_entries.size(); }

    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;
    bool intersect_transmissive(const Ray& ray, SurfaceHit& hit) const override;
    /// Throws rtlab::Error for a hit on a shape not in the list.
    SurfaceInfo surface(const SurfaceHit& hit) const override;

private:
    struct Entry {
        std::shared_ptr<const Shape> shape;
        std::shared_ptr<const Material> material;
        SurfaceFlags flags;
    };
    enum class Filter { all, transmissive };
    bool closest(const Ray& ray, SurfaceHit& hit, Filter filter) const;

    std::vector<Entry> m_entries;
    std::unordered_map<const Shape*, std::size_t> m_index;
};

}  // namespace rtlab
