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
    /// Primitives going below and above (straddlers counted on both sides) when the finder counted them
    /// (the SAH sweep does), else -1.
    std::int64_t below = -1, above = -1;
};

/// \brief Surface-area ratios of the two halves of a box split on one axis, for many planes: the box's
/// extent and inverse area are computed once per node, each plane's halves with the very float operations
/// of AABB::surface_area, so that costs (and trees) match a direct computation bit for bit. Planes must lie
/// strictly inside a non-empty box.
class AreaRatios {
public:
    explicit AreaRatios(const AABB& box) : m_box(box), m_extent(box.extent()), m_inv(1.0f / box.surface_area()) {}
    void operator()(int axis, float position, float& p_left, float& p_right) const {
        Vec3 d = m_extent;
        d[axis] = position - m_box.lo[axis];
        p_left = area(d) * m_inv;
        d[axis] = m_box.hi[axis] - position;
        p_right = area(d) * m_inv;
    }

private:
    static float area(const Vec3& d) { return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x); }
    AABB m_box;
    Vec3 m_extent;
    float m_inv;
};

/// A split event of the SAH sweep: where a primitive (slot in its node's list) starts, ends or lies flat.
/// Sorted by position, then end < planar < start: at one position, primitives ending there leave the
/// right side before those starting there join the left.
enum EventType : std::uint8_t { kEnd = 0, kPlanar = 1, kStart = 2 };
/// 8 bytes (type in the top two bits of the slot's word): the event lists are the bulk of a build's memory
/// traffic -- filtered into the children and merged at every level.
struct Event {
    static constexpr std::uint32_t kSlotMask = (1u << 30) - 1;
    static constexpr std::size_t kMaxSlots = std::size_t{1} << 30;
    float position;
    std::uint32_t key;  ///< type << 30 | slot

    // Leaves the event uninitialized, also in a vector's resize: the builder sizes its lists for the most
    // events first and writes them after.
    Event() {}  // NOLINT(modernize-use-equals-default)
    Event(float p, EventType t, std::uint32_t slot) : position(p), key(static_cast<std::uint32_t>(t) << 30 | slot) {}
    EventType type() const { return static_cast<EventType>(key >> 30); }
    std::uint32_t slot() const { return key & kSlotMask; }
    /// The same event for slot s.
    Event with_slot(std::uint32_t s) const {
        Event e = *this;
        e.key = (key & ~kSlotMask) | s;
        return e;
    }
    /// By position, then type; the order of equal events does not matter to the sweep.
    bool operator<(const Event& o) const {
        return position < o.position || (position == o.position && (key >> 30) < (o.key >> 30));
    }
};
/// The events of the primitives at `slots` of `prims` (the clipped ones of a node's side), sorted, into
/// `events` (replacing what they held).
void sorted_events(std::span<const Prim> prims, std::span<const std::uint32_t> slots,
                   std::array<std::vector<Event>, 3>& events);
/// The root's events of every primitive (slot = index in prims), sorted; the axes in parallel.
std::array<std::vector<Event>, 3> root_events(std::span<const Prim> prims);
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
