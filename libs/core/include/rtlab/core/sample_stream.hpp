#pragma once
/// \brief The random numbers of one camera sample, from a sequence chosen by the renderer, so an integrator draws
/// its dimensions without knowing whether they are independent or low-discrepancy.
///
/// Dimension numbering. Numbers come in 2-D pairs; pair p holds dimensions 2p and 2p + 1 (get1d(2p) is
/// get2d(p).x). The renderer owns pairs 0 (kPixelPair: the offset in the pixel) and 1 (kLensPair: the point on the
/// lens); an integrator numbers its own from kFirstIntegratorPair up, the same pair for the same decision in every
/// sample (a path tracer: pair kFirstIntegratorPair + bounce * pairs_per_bounce + j for its j-th 2-D decision at
/// that bounce, e.g. light choice and light position, BSDF lobe and direction, Russian roulette), because the
/// low-discrepancy sequence stratifies each pair over the samples of a pixel: a pair's points are well spread only
/// if it always serves the same purpose. Two uses of one pair in one sample are correlated; use two pairs.
#include <rtlab/core/low_discrepancy.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/core/sample_hash.hpp>

#include <cstdint>

namespace rtlab {

/// independent: every number an unrelated hash of the key (sample_hash); sobol: each pair an Owen-scrambled Sobol
/// (0,2)-sequence over the sample index, its own randomisation per pixel and pair; sobol_halves: two such sequences
/// per pixel and pair, randomised independently, the even samples walking along one (sample 2j is its point j) and
/// the odd samples along the other.
///
/// Why sobol_halves: a noise estimate from the even and odd half-images needs the two halves to be independent
/// estimates of the pixel. Under `sobol` they are not: they are complementary halves of one stratified point set
/// (the shuffled index splits each aligned pair of points between them), so their errors cancel in the whole image
/// but not in their difference, and (A - B)^2 / 4 measures about what independent samples would leave, not what the
/// stratified set leaves: on a smooth function of the pixel offset at 16 samples, 400 times the true squared error
/// (tests/render/noise_target_test.cpp). The price of independent halves: the image is the mean of two nets of n/2
/// points instead of one net of n, up to twice the RMS error on a smooth 2-D integrand, little on a path tracer's
/// high-dimensional ones.
enum class SampleSequence { independent, sobol, sobol_halves };

inline constexpr std::uint32_t kPixelPair = 0;
inline constexpr std::uint32_t kLensPair = 1;
inline constexpr std::uint32_t kFirstIntegratorPair = 2;

/// sample_hash dimensions of the streams start here, apart from the small numbers integrators pass to
/// sample_hash directly with the same key and from the renderer's kPixelJitterDimension (0x80000000).
inline constexpr std::uint32_t kStreamDimensionBase = 0x40000000u;

/// \brief The numbers of sample `key.sample` of pixel (key.x, key.y): a pure function of the sequence, the key
/// and the dimension, so any sample can be drawn alone, in any order, on any thread. Cheap to copy.
class SampleStream {
public:
    SampleStream(SampleSequence sequence, const SampleKey& key) : m_key(key), m_sequence(sequence) {
        if (sequence != SampleSequence::independent) {
            // The pixel's randomisation leaves out the sample index: the index walks along the sequence. Under
            // sobol_halves each parity has its own randomisation (the sobol one for the even samples) and index.
            SampleKey pixel = key;
            pixel.sample = 0;
            const bool halves = sequence == SampleSequence::sobol_halves;
            const std::uint32_t half = halves ? (key.sample & 1u) : 0u;
            m_pixel_seed = sample_hash(pixel, kStreamDimensionBase + half);
            m_reversed_index = reverse_bits(halves ? key.sample >> 1 : key.sample);
        }
    }

    /// Pair `pair` (dimensions 2 pair and 2 pair + 1), in [0, 1)^2.
    Vec2 get2d(std::uint32_t pair) const {
        if (m_sequence != SampleSequence::independent)
            return sobol_owen_pair_reversed_index(mix_seed(m_pixel_seed + pair), m_reversed_index);
        return sample_uniform2(m_key, kStreamDimensionBase + 2u * pair);
    }
    /// Dimension `dimension`, in [0, 1).
    float get1d(std::uint32_t dimension) const {
        const Vec2 p = get2d(dimension / 2u);
        return (dimension & 1u) ? p.y : p.x;
    }

    const SampleKey& key() const { return m_key; }
    SampleSequence sequence() const { return m_sequence; }

private:
    SampleKey m_key;
    SampleSequence m_sequence;
    std::uint64_t m_pixel_seed = 0;
    /// The point of the (half's) sequence this sample takes, its bits reversed (as the scramble reads it).
    std::uint32_t m_reversed_index = 0;
};

}  // namespace rtlab
