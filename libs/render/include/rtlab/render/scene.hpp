#pragma once
/// \brief The renderer's scene: objects with materials, answering shading's SceneQuery.
#include <rtlab/core/aabb.hpp>
#include <rtlab/geometry/shape.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/shading/scene_query.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rtlab {

/// Objects from which a scene level is a kd-tree over shapes rather than a plain list: the smallest count
/// at which the tree was no slower than the list for both closest hits and shadow rays in
/// docs/data/scene_breakeven.csv (bench/render/scene_bench.cpp, random spheres; medians of 7 interleaved
/// repetitions). Below it the list wins by up to 1.6x, above it the tree by up to 4.7x.
inline constexpr std::size_t kSceneTreeThreshold = 24;

/// Triangles up to which a MeshShape object joins the one flat triangle tree of its scene set (when two or more
/// do): a mesh this small duplicates a few kilobytes at most, while a ray pays a root box test and a walk
/// set-up per mesh tree it meets. Measured on the Cornell box (six meshes, 32 triangles; README, "A race with
/// Blender's Cycles").
inline constexpr std::size_t kSceneFlatMeshTriangles = 1024;

/// \brief One object of a scene: a shape (analytic, a MeshShape, or an Instance of one) and its material.
struct SceneObject {
    std::shared_ptr<const Shape> shape;
    std::shared_ptr<const Material> material;
    SurfaceFlags flags;
    std::string name;  ///< for error messages and statistics; may be empty
};

/// \brief How a Scene builds its structures.
struct SceneOptions {
    /// A query structure over this many objects or more is a kd-tree, fewer a plain list. 0 or 1: always a
    /// tree; SIZE_MAX: always a list.
    std::size_t tree_threshold = kSceneTreeThreshold;
    /// MeshShape objects (not Instances) of at most this many triangles, kd-trees with the watertight test,
    /// share one triangle tree per set when two or more qualify; 0: every mesh keeps its own tree only.
    std::size_t flat_mesh_triangles = kSceneFlatMeshTriangles;
};

/// \brief The objects of a render and the structures that answer the Whitted recursion's queries.
///
/// Three sets, each a plain list or a kd-tree over shapes by its own size: every object (intersect), the
/// opaque shadow casters (occluded: any-hit), the transmissive shadow casters (material->transmits_shadows();
/// intersect_transmissive). Objects with flags.casts_shadows false are in neither shadow set. Shapes are used
/// as they are: analytic shapes stay analytic, a MeshShape carries its own tree, and Instances of one
/// MeshShape share it; but small MeshShape objects of a set (SceneOptions::flat_mesh_triangles) are found
/// through one triangle tree over all of them, with the same t and record their own trees give. A hit's shape is the
/// object's own (outermost) shape, so instances of one mesh can carry different materials. Immutable after construction
/// and safe to query from several threads.
class Scene final : public SceneQuery {
public:
    /// Throws rtlab::Error for an object without a shape or a material, or a shape given to two objects
    /// (show one shape twice through Instances).
    explicit Scene(std::vector<SceneObject> objects, SceneOptions options = {});
    ~Scene() override;
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const Ray& ray) const override;
    bool intersect_transmissive(const Ray& ray, SurfaceHit& hit) const override;
    /// Throws rtlab::Error for a hit on a shape that is not one of the scene's objects.
    SurfaceInfo surface(const SurfaceHit& hit) const override;
    /// A list's hit knows its object: no search by shape. Spheres of materials without textures skip their uv.
    bool intersect_surface(const Ray& ray, SurfaceHit& hit, SurfaceInfo& info) const override;
    ShadowHit shadow(const Ray& ray, bool check_opaque, SurfaceHit& hit, SurfaceInfo& info) const override;
    /// The rays go through the meshes' accelerators together (MeshShape objects and Instances of one, and the flat
    /// triangle tree), every other object one ray at a time, each ray meeting the objects in the single query's
    /// order with its tmax: the answers are intersect_surface()'s and occluded()'s, bit for bit.
    void intersect_surface_packet(std::span<const Ray> rays, std::span<SurfaceHit> hits, std::span<SurfaceInfo> infos,
                                  std::span<std::uint8_t> found) const override;
    void occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const override;
    /// Whether some object's mesh (or the flat tree) traces packets.
    bool traces_packets() const override;

    /// What answers intersect(): "list" or "kd-tree", for the statistics.
    std::string_view structure() const;
    /// How many objects' meshes intersect() finds through the flat triangle tree (0: none).
    std::size_t flat_meshes() const;
    std::size_t object_count() const { return m_objects.size(); }
    const std::vector<SceneObject>& objects() const { return m_objects; }
    /// The union of every object's bounds (empty for an empty scene).
    AABB bounds() const { return m_bounds; }
    /// Heap bytes of the scene-level structures (lists, trees, the shape-to-object index), not of the shapes.
    std::size_t structure_bytes() const;

    class Set;  // a list or a kd-tree over some of the objects (scene.cpp)

private:
    SurfaceInfo info(std::size_t object, const SurfaceHit& hit) const;

    std::vector<SceneObject> m_objects;
    std::vector<std::pair<const Shape*, std::size_t>> m_index;  // sorted by shape, for surface()
    AABB m_bounds;
    std::unique_ptr<Set> m_all, m_opaque, m_transmissive;
    bool m_opaque_is_all = false;  // every object is an opaque caster: occluded() uses m_all
};

}  // namespace rtlab
