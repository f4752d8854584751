#pragma once
/// \brief The lights of a sampling integrator: chosen in proportion to their power, and found from the shape a
/// ray hits.
#include <rtlab/geometry/shape.hpp>
#include <rtlab/shading/emitter.hpp>

#include <memory>
#include <unordered_map>
#include <vector>

namespace rtlab {

/// \brief Emitters with their selection probabilities (channel mean of power() over the total), the emitting
/// shapes' own, and the environment (uniform or a map) if there is one.
class LightSet {
public:
    struct Entry {
        std::shared_ptr<const Emitter> emitter;
        float probability = 0.0f;  ///< of being chosen by choose()
    };

    LightSet() = default;
    /// Throws rtlab::Error for a null emitter or a non-finite power. Emitters of no power are kept (a hit finds
    /// them) but never chosen.
    void add(std::shared_ptr<const Emitter> emitter, const Shape* shape = nullptr);
    /// The environment, which rays that escape see: also added as an emitter. At most one (rtlab::Error).
    void set_environment(std::shared_ptr<const EnvironmentEmitter> environment);
    /// Works out the probabilities; call once after the last add().
    void finish();

    /// The emitter for u in [0, 1), or nullptr when no light has power.
    const Entry* choose(float u) const;
    /// Whether choose() depends on u: false for a single entry, so an integrator may leave that number undrawn.
    bool choice_uses_u() const { return m_entries.size() > 1; }
    /// The emitter of an emitting shape (the outermost shape a hit reports), or nullptr.
    const Entry* for_shape(const Shape* shape) const {
        const auto it = m_by_shape.find(shape);
        return it == m_by_shape.end() ? nullptr : &m_entries[it->second];
    }
    const Entry* environment() const { return m_environment < 0 ? nullptr : &m_entries[m_environment]; }
    const EnvironmentEmitter* environment_emitter() const { return m_environment_emitter.get(); }
    const std::vector<Entry>& entries() const { return m_entries; }
    bool empty() const { return m_entries.empty(); }

private:
    std::vector<Entry> m_entries;
    std::vector<float> m_cdf;  // cumulative probability of the entries, last 1
    std::unordered_map<const Shape*, std::size_t> m_by_shape;
    std::shared_ptr<const EnvironmentEmitter> m_environment_emitter;
    int m_environment = -1;
};

}  // namespace rtlab
