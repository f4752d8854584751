#pragma once
/// \brief The surface area heuristic's constants, in one small validated class.
#include <rtlab/core/error.hpp>

#include <cmath>
#include <cstdint>
#include <string>

namespace rtlab {

/// \brief Cost of a split: traversal + intersection * (P_left N_left + P_right N_right) * (1 - empty_bonus
/// when a side is empty), with P the surface-area ratios; a leaf costs intersection * N.
class KdCostModel {
public:
    KdCostModel(float traversal = 1.0f, float intersection = 0.3f, float empty_bonus = 0.2f)
        : m_traversal(traversal), m_intersection(intersection), m_empty_bonus(empty_bonus) {
        if (!(traversal > 0.0f && std::isfinite(traversal)) || !(intersection > 0.0f && std::isfinite(intersection)))
            throw Error("kd cost model: traversal and intersection costs must be positive and finite");
        if (!(empty_bonus >= 0.0f && empty_bonus < 1.0f))
            throw Error("kd cost model: empty bonus must lie in [0, 1), got " + std::to_string(empty_bonus));
    }

    float traversal() const { return m_traversal; }
    float intersection() const { return m_intersection; }
    float empty_bonus() const { return m_empty_bonus; }

    float leaf_cost(std::size_t n) const { return m_intersection * static_cast<float>(n); }
    /// p_left, p_right: surface area of each side over the node's.
    float split_cost(float p_left, float p_right, std::size_t n_left, std::size_t n_right) const {
        const float bonus = (n_left == 0 || n_right == 0) ? 1.0f - m_empty_bonus : 1.0f;
        // Counts go through a signed integer: the same float, but one instruction instead of the unsigned
        // 64-bit conversion's branches (this runs once per candidate plane of every node).
        return m_traversal + bonus * m_intersection *
                                 (p_left * static_cast<float>(static_cast<std::int64_t>(n_left)) +
                                  p_right * static_cast<float>(static_cast<std::int64_t>(n_right)));
    }

private:
    float m_traversal;
    float m_intersection;
    float m_empty_bonus;
};

}  // namespace rtlab
