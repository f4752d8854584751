#pragma once
/// \brief Piecewise-constant densities on [0, 1) and [0, 1)^2, sampled by inverting their cumulative
/// distribution: how an environment map (and anything else given as a table of weights) is importance-sampled.
///
/// A table of n weights f_i >= 0 defines the density f_i / (mean of f) on the cell [i / n, (i + 1) / n). The
/// cumulative table is summed in double and stored in float; sampling finds the cell by binary search over it and
/// places the point linearly within the cell, so a cell of weight 0 (a zero step of the table) is never drawn.
/// A table of all zeros falls back to the uniform density (integral() says it was zero).
#include <rtlab/core/math.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace rtlab {

/// \brief A piecewise-constant density on [0, 1) from n >= 1 weights.
class Distribution1D {
public:
    /// \brief One draw: the point, its density and its cell.
    struct Sample {
        float x = 0.0f;    ///< in [0, 1)
        float pdf = 0.0f;  ///< density at x (> 0)
        std::size_t index = 0;
    };

    Distribution1D() = default;
    /// Throws rtlab::Error for no weights or a weight that is negative or not finite.
    explicit Distribution1D(std::span<const float> weights);

    std::size_t size() const { return m_weights.size(); }
    /// The mean of the weights: the integral of the function they tabulate over [0, 1).
    double integral() const { return m_integral; }
    /// u in [0, 1) to x in [0, 1): the inverse of the cumulative distribution.
    Sample sample(float u) const;
    /// The density of cell i (weight / integral; 1 everywhere for an all-zero table).
    float pdf_of(std::size_t i) const;
    /// The density at x in [0, 1) (x outside is clamped into the first or last cell).
    float pdf(float x) const { return pdf_of(cell(x)); }
    /// The cumulative distribution at the start of cell i (cdf(0) = 0, cdf(size()) = 1).
    float cdf(std::size_t i) const { return m_cdf[i]; }
    /// The cell holding x.
    std::size_t cell(float x) const;

private:
    std::vector<float> m_weights;
    std::vector<float> m_cdf;  // size() + 1 entries, 0 to 1
    double m_integral = 0.0;
};

/// \brief A piecewise-constant density on [0, 1)^2 from an nu x nv table of weights (row-major: nv rows of nu
/// columns; u across a row, v down the rows): v drawn from the rows' marginal, then u from that row's conditional.
class Distribution2D {
public:
    /// \brief One draw: the point, its density over [0, 1)^2, and its cell.
    struct Sample {
        Vec2 uv{0.0f};
        float pdf = 0.0f;
        std::size_t column = 0, row = 0;
    };

    Distribution2D() = default;
    /// Throws rtlab::Error for a size of 0, a table of another size than nu x nv, or a bad weight.
    Distribution2D(std::span<const float> weights, std::size_t nu, std::size_t nv);

    std::size_t columns() const { return m_rows.empty() ? 0 : m_rows.front().size(); }
    std::size_t rows() const { return m_rows.size(); }
    /// The mean of the weights.
    double integral() const { return m_marginal.integral(); }
    /// u in [0, 1)^2 to a point of [0, 1)^2: u.y picks the row (uv.y) from the marginal, u.x the column (uv.x)
    /// from that row's conditional.
    Sample sample(const Vec2& u) const;
    /// The density at uv in [0, 1)^2 (clamped into the table).
    float pdf(const Vec2& uv) const;
    /// The density on the cell of `column` and `row`.
    float pdf_of(std::size_t column, std::size_t row) const {
        return m_marginal.pdf_of(row) * m_rows[row].pdf_of(column);
    }
    const Distribution1D& marginal() const { return m_marginal; }
    const Distribution1D& conditional(std::size_t row) const { return m_rows[row]; }

private:
    std::vector<Distribution1D> m_rows;
    Distribution1D m_marginal;
};

}  // namespace rtlab
