#pragma once
/// \brief What the renderer asks of the shading: the radiance arriving along a camera ray.
#include <rtlab/core/color.hpp>
#include <rtlab/core/ray.hpp>
#include <rtlab/core/sample_hash.hpp>
#include <rtlab/shading/whitted.hpp>

#include <cstdint>
#include <functional>

namespace rtlab {

/// \brief Rays traced, by kind: shading's RayStats (shadow, reflected, refracted) plus the camera rays, so
/// a Whitted integrator counts straight into the renderer's counters. Plain integers, filled per tile and
/// added up, so the totals never depend on the thread count or on the order in which tiles finish.
struct RayCounters : RayStats {
    std::uint64_t camera = 0;

    std::uint64_t total() const { return camera + shadow + reflected + refracted; }
    RayCounters& operator+=(const RayCounters& o) {
        RayStats::operator+=(o);
        camera += o.camera;
        return *this;
    }
    friend bool operator==(const RayCounters& a, const RayCounters& b) {
        return a.camera == b.camera && a.shadow == b.shadow && a.reflected == b.reflected && a.refracted == b.refracted;
    }
};

/// \brief The radiance computation the renderer calls for every camera ray (a Whitted integrator, or an
/// analytic function in tests and benchmarks). Called concurrently from several threads: it must be
/// thread-safe and, for images that do not depend on the thread count, a pure function of its arguments.
class RadianceSource {
public:
    virtual ~RadianceSource() = default;
    /// Radiance arriving at the camera along `ray`. `key` names the camera sample (seed, lattice
    /// position, sample index, bounce 0); random numbers come from sample_uniform(key, dimension) with
    /// dimensions below kPixelJitterDimension. The renderer counts the camera ray itself; the source adds
    /// the shadow, reflected and refracted rays it traces to `counters`.
    virtual RGB radiance(const Ray& ray, const SampleKey& key, RayCounters& counters) const = 0;
};

/// \brief A RadianceSource made of a callable.
class FunctionRadiance final : public RadianceSource {
public:
    using Function = std::function<RGB(const Ray&, const SampleKey&, RayCounters&)>;
    explicit FunctionRadiance(Function f) : m_f(std::move(f)) {}
    RGB radiance(const Ray& ray, const SampleKey& key, RayCounters& counters) const override {
        return m_f(ray, key, counters);
    }

private:
    Function m_f;
};

}  // namespace rtlab
