#pragma once
/// \brief Building kd-trees from primitive bounds, by strategy name.
#include <rtlab/accel/kd_cost_model.hpp>
#include <rtlab/accel/kd_node.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// The build strategies (see DESIGN.md for their names).
enum class KdStrategy { sah, sah_binned, sah_naive, median, midpoint };

/// Every strategy, in the order listings show them: the one list the kd-tree method names come from.
inline constexpr KdStrategy kKdStrategies[] = {KdStrategy::sah, KdStrategy::sah_binned, KdStrategy::sah_naive,
                                               KdStrategy::median, KdStrategy::midpoint};

/// "kd-sah", "kd-sah-binned", "kd-sah-naive", "kd-median", "kd-midpoint".
std::string_view kd_strategy_name(KdStrategy s);
/// Throws rtlab::Error listing the known names for an unknown one.
KdStrategy parse_kd_strategy(std::string_view name);

/// \brief What a builder needs: each primitive's bounds and, for perfect splits, the bounds of primitive
/// i clipped to a box (empty when it does not reach into the box). Without `clip`, bounds are clipped
/// box against box. Primitives with empty bounds are left out of the tree.
struct KdBuildInput {
    std::vector<AABB> bounds;
    std::function<AABB(std::uint32_t, const AABB&)> clip;
};

/// Builds a tree; threads = 0 lets oneTBB choose. Fills stats (except bytes of the caller's own data).
KdTreeData build_kd_tree(const KdBuildInput& input, KdStrategy strategy, const KdCostModel& cost = {}, int threads = 0);

}  // namespace rtlab
