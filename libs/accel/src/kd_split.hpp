#pragma once
// Split finders shared by the kd-tree build strategies (private to the accel library).
#include <rtlab/accel/kd_cost_model.hpp>
#include <rtlab/core/aabb.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace rtlab::kd {

/// A primitive in a node: its index and its bounds clipped to the node.
struct Prim {
    std::uint32_t index;
    AABB box;
};

/// A chosen split; axis < 0 means "make a leaf".
struct Split {
    int axis = -1;
    float position = 0.0f;
    bool planar_left = true;  ///< where primitives lying in the split plane go
    float cost = 0.0f;
};

/// Surface-area ratios of the two halves of `box` split at `position` on `axis`.
inline void area_ratios(const AABB& box, int axis, float position, float& p_left, float& p_right) {
    AABB left = box, right = box;
    left.hi[axis] = position;
    right.lo[axis] = position;
    const float inv = 1.0f / box.surface_area();
    p_left = left.surface_area() * inv;
    p_right = right.surface_area() * inv;
}

/// A split event of the SAH sweep: where a primitive (slot in its node's list) starts, ends or lies flat.
/// Sorted by position, then end < planar < start: at one position, primitives ending there leave the
/// right side before those starting there join the left.
enum EventType : std::uint8_t { kEnd = 0, kPlanar = 1, kStart = 2 };
struct Event {
    float position;
    EventType type;
    std::uint32_t slot;
    bool operator<(const Event& o) const { return position < o.position || (position == o.position && type < o.type); }
};
/// Appends the events of one primitive box to the three axes' lists.
void add_events(const AABB& box, std::uint32_t slot, std::array<std::vector<Event>, 3>& events);
void sort_events(std::array<std::vector<Event>, 3>& events);
/// The best SAH split from sorted events of n primitives; a leaf (axis < 0) when none beats it.
Split sweep_sah(const std::array<std::vector<Event>, 3>& events, std::size_t n, const AABB& box,
                const KdCostModel& cost);
Split find_split_binned(std::span<const Prim> prims, const AABB& box, const KdCostModel& cost);
Split find_split_naive(std::span<const Prim> prims, const AABB& box, const KdCostModel& cost);
Split find_split_median(std::span<const Prim> prims, const AABB& box, int depth);
Split find_split_midpoint(std::span<const Prim> prims, const AABB& box);

/// Leaves of the spatial (non-SAH) strategies hold at most this many primitives.
inline constexpr std::size_t kSpatialLeafSize = 4;

}  // namespace rtlab::kd
