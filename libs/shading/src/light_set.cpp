#include <rtlab/core/error.hpp>
#include <rtlab/shading/light_set.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {

void LightSet::add(std::shared_ptr<const Emitter> emitter, const Shape* shape) {
    if (!emitter) throw Error("light set: null emitter");
    const float p = channel_mean(emitter->power());
    if (!std::isfinite(p) || p < 0.0f) throw Error("light set: a light's power is not finite");
    if (shape) m_by_shape[shape] = m_entries.size();
    m_entries.push_back({std::move(emitter), 0.0f});
}

void LightSet::set_environment(std::shared_ptr<const EnvironmentEmitter> environment) {
    if (!environment) throw Error("light set: null environment");
    if (m_environment >= 0) throw Error("light set: a second environment (there is one environment at most)");
    m_environment = static_cast<int>(m_entries.size());
    add(environment);
    m_environment_emitter = std::move(environment);
}

void LightSet::finish() {
    double total = 0.0;
    for (const Entry& e : m_entries) total += channel_mean(e.emitter->power());
    m_cdf.clear();
    double sum = 0.0;
    for (Entry& e : m_entries) {
        const double p = channel_mean(e.emitter->power());
        e.probability = total > 0.0 ? static_cast<float>(p / total) : 0.0f;
        sum += p;
        m_cdf.push_back(total > 0.0 ? static_cast<float>(sum / total) : 0.0f);
    }
}

const LightSet::Entry* LightSet::choose(float u) const {
    // One entry (a lone light: the common case) is the search's answer for every u: its cumulative probability is
    // 1 when it has power, and then so is its probability; 0 for both when not (or before finish()).
    if (m_entries.size() == 1) return m_entries[0].probability > 0.0f ? &m_entries[0] : nullptr;
    if (m_cdf.empty() || !(m_cdf.back() > 0.0f)) return nullptr;
    // The first entry whose cumulative probability exceeds u; one of no power has none of the interval.
    const auto it = std::upper_bound(m_cdf.begin(), m_cdf.end(), u);
    std::size_t i = static_cast<std::size_t>(it - m_cdf.begin());
    if (i >= m_entries.size()) i = m_entries.size() - 1;
    while (i > 0 && !(m_entries[i].probability > 0.0f)) --i;
    return m_entries[i].probability > 0.0f ? &m_entries[i] : nullptr;
}

}  // namespace rtlab
