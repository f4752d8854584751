#pragma once
/// \brief The rays one object of a scene really answers in a render, recorded in its shape's own space: what
/// its mesh's accelerator receives, for replaying a renderer's workload against another structure
/// (`rtlab-render --record-rays NAME`, then `rtlab-accel --rays FILE`).
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/ray.hpp>
#include <rtlab/render/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string_view>
#include <vector>

namespace rtlab {

/// \brief Closest-hit and any-hit (shadow) queries kept apart, each with what the shape answered.
///
/// A query is kept when its segment [tmin, tmax] overlaps `bounds` (AABB::intersect, the trees' own slab test),
/// up to `max_per_kind` of each kind; later ones are only counted. Safe to call from several threads, but the
/// order of the queries is then the threads' interleaving: record on one thread for a reproducible file.
class RayRecorder {
public:
    /// What a closest-hit query found: t and the primitive (kNoPrimitive and +inf for a miss).
    struct Answer {
        float t;
        std::uint32_t primitive;
    };
    /// Queries the shape answered, those whose segment overlaps its bounds, and those kept (the cap).
    struct Counts {
        std::uint64_t answered = 0, overlapping = 0, kept = 0;
    };

    RayRecorder(const AABB& bounds, std::size_t max_per_kind);

    /// Adds a closest-hit query and its answer (when it overlaps the bounds and the cap is not reached).
    void closest(const Ray& ray, bool hit, const Answer& answer);
    /// Adds an any-hit query and whether something blocked it.
    void shadow(const Ray& ray, bool blocked);

    /// The kept queries, in the order they came; read them once the render is over.
    const std::vector<Ray>& closest_rays() const { return m_closest; }
    const std::vector<Answer>& closest_answers() const { return m_answers; }
    const std::vector<Ray>& shadow_rays() const { return m_shadow; }
    const std::vector<std::uint8_t>& shadow_blocked() const { return m_blocked; }
    Counts closest_counts() const;
    Counts shadow_counts() const;
    const AABB& bounds() const { return m_bounds; }
    std::size_t max_per_kind() const { return m_max; }

private:
    AABB m_bounds;
    std::size_t m_max;
    mutable std::mutex m_mutex;
    std::vector<Ray> m_closest, m_shadow;
    std::vector<Answer> m_answers;
    std::vector<std::uint8_t> m_blocked;
    std::uint64_t m_closest_answered = 0, m_closest_overlapping = 0;
    std::uint64_t m_shadow_answered = 0, m_shadow_overlapping = 0;
};

/// Makes the object named `name` record what its innermost shape answers: a decorator around that shape (under
/// every Instance, rebuilt with the same matrices, so the rays are those the shape itself receives, in its object
/// space, and its answers unchanged) that passes each intersect() and occluded() on and records it. Returns the
/// recorder, whose bounds are the innermost shape's. Build the Scene from `objects` after this call; a MeshShape
/// recorded so no longer joins the scene's flat tree of small meshes (it answers through its own tree, with the
/// same hits). Throws rtlab::Error for no object of that name (listing the names there are) or an object that
/// emits light (its area light samples the shape itself, which the decorator would hide).
std::shared_ptr<RayRecorder> record_object_rays(std::vector<SceneObject>& objects, std::string_view name,
                                                std::size_t max_per_kind);

}  // namespace rtlab
