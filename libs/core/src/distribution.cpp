#include <rtlab/core/distribution.hpp>
#include <rtlab/core/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace rtlab {

namespace {

// The largest float below 1: a uniform number is kept inside [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

}  // namespace

Distribution1D::Distribution1D(std::span<const float> weights) : m_weights(weights.begin(), weights.end()) {
    if (m_weights.empty()) throw Error("distribution: no weights");
    double sum = 0.0;
    for (std::size_t i = 0; i < m_weights.size(); ++i) {
        const float w = m_weights[i];
        if (!(w >= 0.0f) || !std::isfinite(w))
            throw Error("distribution: weight " + std::to_string(i) + " is " + std::to_string(w) +
                        "; weights must be finite and >= 0");
        sum += w;
    }
    const auto n = static_cast<double>(m_weights.size());
    m_integral = sum / n;
    m_cdf.resize(m_weights.size() + 1);
    m_cdf[0] = 0.0f;
    double running = 0.0;
    for (std::size_t i = 0; i < m_weights.size(); ++i) {
        // Equal running sums round to equal floats: a cell of weight 0 keeps a step of exactly 0.
        running += sum > 0.0 ? static_cast<double>(m_weights[i]) : 1.0;
        m_cdf[i + 1] = static_cast<float>(running / (sum > 0.0 ? sum : n));
    }
    m_cdf.back() = 1.0f;
}

std::size_t Distribution1D::cell(float x) const {
    const auto n = m_weights.size();
    if (!(x > 0.0f)) return 0;
    return std::min(n - 1, static_cast<std::size_t>(x * static_cast<float>(n)));
}

float Distribution1D::pdf_of(std::size_t i) const {
    if (!(m_integral > 0.0)) return 1.0f;
    return static_cast<float>(static_cast<double>(m_weights[i]) / m_integral);
}

Distribution1D::Sample Distribution1D::sample(float u) const {
    const std::size_t n = m_weights.size();
    u = std::clamp(u, 0.0f, kOneMinusEpsilon);
    // The cell whose step holds u: the last start <= u before the first entry above u. A cell of weight 0 has
    // a step of width 0 and is never the answer.
    const auto above = std::upper_bound(m_cdf.begin(), m_cdf.end(), u);
    std::size_t i = static_cast<std::size_t>(above - m_cdf.begin());
    i = i == 0 ? 0 : std::min(i - 1, n - 1);
    const float lo = m_cdf[i], width = m_cdf[i + 1] - lo;
    const double t = width > 0.0f ? std::clamp(static_cast<double>(u - lo) / width, 0.0, 1.0) : 0.5;
    float x = static_cast<float>((static_cast<double>(i) + t) / static_cast<double>(n));
    // Rounding must not carry x into a neighbouring cell (which may be one of weight 0), nor out of [0, 1).
    x = std::min(x, kOneMinusEpsilon);
    while (cell(x) > i) x = next_float_down(x);
    while (cell(x) < i) x = next_float_up(x);
    return {x, pdf_of(i), i};
}

Distribution2D::Distribution2D(std::span<const float> weights, std::size_t nu, std::size_t nv) {
    if (nu == 0 || nv == 0) throw Error("distribution: a table of " + std::to_string(nu) + "x" + std::to_string(nv));
    if (weights.size() != nu * nv)
        throw Error("distribution: " + std::to_string(weights.size()) + " weights for a table of " +
                    std::to_string(nu) + "x" + std::to_string(nv));
    m_rows.reserve(nv);
    std::vector<float> row_integrals(nv);
    for (std::size_t r = 0; r < nv; ++r) {
        m_rows.emplace_back(weights.subspan(r * nu, nu));
        row_integrals[r] = static_cast<float>(m_rows.back().integral());
    }
    m_marginal = Distribution1D(row_integrals);
}

Distribution2D::Sample Distribution2D::sample(const Vec2& u) const {
    const Distribution1D::Sample v = m_marginal.sample(u.y);
    const Distribution1D::Sample c = m_rows[v.index].sample(u.x);
    return {Vec2(c.x, v.x), v.pdf * c.pdf, c.index, v.index};
}

float Distribution2D::pdf(const Vec2& uv) const {
    const std::size_t r = m_marginal.cell(uv.y);
    return pdf_of(m_rows[r].cell(uv.x), r);
}

}  // namespace rtlab
