#pragma once
/// \brief What the renderer asks of the shading: the radiance arriving along a camera ray.
#include <rtlab/core/color.hpp>
#include <rtlab/core/ray.hpp>
#include <rtlab/core/sample_hash.hpp>
#include <rtlab/core/sample_stream.hpp>
#include <rtlab/shading/whitted.hpp>

#include <cstdint>
#include <functional>
#include <span>

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

/// \brief A camera sample as the progressive renderer hands it over: the camera ray and the sample's numbers.
/// stream.key() names it (seed, pixel x and y, sample index, bounce 0); the renderer has used the stream's pairs
/// kPixelPair and kLensPair for the ray; the integrator draws its own from kFirstIntegratorPair up
/// (rtlab/core/sample_stream.hpp documents the numbering).
struct CameraSample {
    Ray ray;
    SampleStream stream;
};

/// \brief The radiance computation the renderer calls for every camera ray (a Whitted integrator, or an
/// analytic function in tests and benchmarks). Called concurrently from several threads: it must be
/// thread-safe and, for images that do not depend on the thread count, a pure function of its arguments.
class RadianceSource {
public:
    virtual ~RadianceSource() = default;
    /// Radiance arriving at the camera along `ray`. `key` names the camera sample (seed, lattice
    /// position, sample index, bounce 0); random numbers come from sample_uniform(key, dimension) with
    /// dimensions below kStreamDimensionBase. The renderer counts the camera ray itself; the source adds
    /// the shadow, reflected and refracted rays it traces to `counters`.
    virtual RGB radiance(const Ray& ray, const SampleKey& key, RayCounters& counters) const = 0;

    /// Radiance for a camera sample of the progressive renderer. An integrator that draws its numbers from the
    /// sample's stream (low-discrepancy with PixelPattern::sobol) overrides this; the default ignores the stream and
    /// calls radiance(ray, key), whose hashed numbers are independent of the stream's.
    virtual RGB sample_radiance(const CameraSample& sample, RayCounters& counters) const {
        return radiance(sample.ray, sample.stream.key(), counters);
    }

    /// The entry point for groups of coherent rays: out[i] = the radiance of samples[i], for a group the
    /// renderers form from one sample index over neighbouring pixels of a tile (up to two pixel rows, row-major, so
    /// 4x2 and 8x2 blocks are contiguous in pairs of row runs) or from adaptive sampling's pixel corners (up to three
    /// rows of them). `out` has samples.size() elements.
    /// The default calls sample_radiance() in order; a packet tracer overrides it. Results must equal what
    /// sample_radiance() gives for each sample alone, so images do not depend on how samples are grouped.
    virtual void radiance_batch(std::span<const CameraSample> samples, std::span<RGB> out,
                                RayCounters& counters) const {
        for (std::size_t i = 0; i < samples.size(); ++i) out[i] = sample_radiance(samples[i], counters);
    }

    /// True when radiance_batch() traces a group faster than one sample at a time (a packet tracer over a scene it
    /// has packets for). A renderer that pays to form its groups -- adaptive sampling decides which points it needs
    /// ahead of its recursion -- forms them only then.
    virtual bool traces_batches() const { return false; }
};

/// \brief A radiance source that draws every number of a sample from a SampleStream: the progressive renderer's
/// camera samples bring theirs (low-discrepancy with PixelPattern::sobol), and radiance(ray, key) uses the
/// independent stream of the key. An integrator implements estimate() alone.
class StreamRadianceSource : public RadianceSource {
public:
    RGB radiance(const Ray& ray, const SampleKey& key, RayCounters& counters) const final {
        return estimate(ray, SampleStream(SampleSequence::independent, key), counters);
    }
    RGB sample_radiance(const CameraSample& sample, RayCounters& counters) const final {
        return estimate(sample.ray, sample.stream, counters);
    }
    /// One camera sample's radiance with its numbers from `stream`; adds the rays it traces to `stats`.
    virtual RGB estimate(const Ray& ray, const SampleStream& stream, RayStats& stats) const = 0;
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
