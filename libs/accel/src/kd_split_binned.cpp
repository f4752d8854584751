// Binned SAH: 32 candidate planes per axis at equal spacing, counted in one pass over the primitives.
// The fast-build variant: a little worse trees, far less sorting.
#include "kd_split.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <array>
#include <cstddef>
#include <cstdint>

namespace rtlab::kd {

Split find_split_binned(std::span<const Prim> prims, const AABB& box, const KdCostModel& cost) {
    constexpr int kBins = 32;
    Split best;
    best.cost = cost.leaf_cost(prims.size());
    if (box.surface_area() <= 0.0f) return {};
    const AreaRatios ratios(box);
    // The three axes binned in one pass over the primitives (one read of each box, not three). An axis without
    // extent gets scale 0 and its counts are not used. A box's bin is int(t) clamped to [0, kBins - 1] for
    // t = (coordinate - lo) * scale, clamped here before the conversion: the same bin for every t, without a
    // conversion's undefined result for a t beyond an int (or NaN, which takes bin 0 as that result did).
    float lo[3], scale[3];
    bool active[3];
    for (int axis = 0; axis < 3; ++axis) {
        const float extent = box.hi[axis] - box.lo[axis];
        lo[axis] = box.lo[axis];
        active[axis] = extent > 0.0f;
        scale[axis] = active[axis] ? kBins / extent : 0.0f;
    }
    std::array<std::array<std::uint32_t, kBins>, 3> starts{}, ends{};  // fewer than 2^30 primitives
#if defined(__SSE2__)
    // A box's six bins in two vectors of four lanes, the very float operations of the scalar form per lane
    // (the bins of the lanes that repeat one are counted once). MAXPS answers its second operand for a NaN.
    static_assert(offsetof(AABB, hi) == offsetof(AABB, lo) + 3 * sizeof(float));
    const __m128 lo_a = _mm_setr_ps(lo[0], lo[1], lo[2], lo[0]),
                 scale_a = _mm_setr_ps(scale[0], scale[1], scale[2], scale[0]);
    const __m128 lo_b = _mm_setr_ps(lo[2], lo[0], lo[1], lo[2]),
                 scale_b = _mm_setr_ps(scale[2], scale[0], scale[1], scale[2]);
    const __m128 zero = _mm_setzero_ps(), last = _mm_set1_ps(static_cast<float>(kBins - 1));
    for (const Prim& p : prims) {
        const auto* box_floats = reinterpret_cast<const float*>(&p.box);
        const __m128 a = _mm_loadu_ps(box_floats);      // lo.x lo.y lo.z hi.x
        const __m128 b = _mm_loadu_ps(box_floats + 2);  // lo.z hi.x hi.y hi.z
        alignas(16) std::int32_t bin_a[4], bin_b[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(bin_a),
                        _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(_mm_mul_ps(_mm_sub_ps(a, lo_a), scale_a), zero), last)));
        _mm_store_si128(reinterpret_cast<__m128i*>(bin_b),
                        _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(_mm_mul_ps(_mm_sub_ps(b, lo_b), scale_b), zero), last)));
        ++starts[0][static_cast<std::size_t>(bin_a[0])];
        ++starts[1][static_cast<std::size_t>(bin_a[1])];
        ++starts[2][static_cast<std::size_t>(bin_a[2])];
        ++ends[0][static_cast<std::size_t>(bin_a[3])];
        ++ends[1][static_cast<std::size_t>(bin_b[2])];
        ++ends[2][static_cast<std::size_t>(bin_b[3])];
    }
#else
    auto bin = [&](float coordinate, int axis) {
        const float t = (coordinate - lo[axis]) * scale[axis];
        const float at_least_0 = t >= 0.0f ? t : 0.0f;
        return static_cast<int>(at_least_0 < kBins - 1 ? at_least_0 : static_cast<float>(kBins - 1));
    };
    for (const Prim& p : prims)
        for (int axis = 0; axis < 3; ++axis) {
            ++starts[static_cast<std::size_t>(axis)][static_cast<std::size_t>(bin(p.box.lo[axis], axis))];
            ++ends[static_cast<std::size_t>(axis)][static_cast<std::size_t>(bin(p.box.hi[axis], axis))];
        }
#endif
    for (int axis = 0; axis < 3; ++axis) {
        if (!active[axis]) continue;
        const float extent = box.hi[axis] - box.lo[axis];
        const auto& axis_starts = starts[static_cast<std::size_t>(axis)];
        const auto& axis_ends = ends[static_cast<std::size_t>(axis)];
        // Plane k sits at the lower border of bin k: left holds primitives starting in bins < k, right
        // those ending in bins >= k (a primitive spanning the plane counts on both sides).
        std::size_t n_left = 0, n_right = prims.size();
        for (int k = 1; k < kBins; ++k) {
            n_left += axis_starts[static_cast<std::size_t>(k - 1)];
            n_right -= axis_ends[static_cast<std::size_t>(k - 1)];
            const float position = lo[axis] + static_cast<float>(k) * (extent / kBins);
            if (!(position > box.lo[axis] && position < box.hi[axis])) continue;
            float p_left, p_right;
            ratios(axis, position, p_left, p_right);
            const float c = cost.split_cost(p_left, p_right, n_left, n_right);
            if (c < best.cost) best = {axis, position, true, c};
        }
    }
    return best;
}

}  // namespace rtlab::kd
