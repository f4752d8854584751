#pragma once
/// \brief Sums of noise octaves: fractional Brownian motion and turbulence, over any 2D/3D noise.
#include <cmath>

namespace rtlab {

/// \brief Octave parameters: octave k has frequency lacunarity^k and amplitude gain^k.
struct FractalParams {
    int octaves = 6;
    double lacunarity = 2.0;
    float gain = 0.5f;
};

namespace detail {
template <class Sample>
float octave_sum(const FractalParams& f, Sample&& sample) {
    double frequency = 1.0;
    float amplitude = 1.0f, sum = 0.0f, norm = 0.0f;
    for (int k = 0; k < f.octaves; ++k) {
        sum += amplitude * sample(frequency);
        norm += amplitude;
        frequency *= f.lacunarity;
        amplitude *= f.gain;
    }
    return norm > 0.0f ? sum / norm : 0.0f;
}
}  // namespace detail

/// fBm normalised by the sum of amplitudes, so it stays in the range of the noise ([-1, 1]).
/// Frequencies are applied in double: the octave coordinates stay exact far from the origin.
template <class Noise>
float fbm(const Noise& noise, double x, double y, double z, const FractalParams& f) {
    return detail::octave_sum(f, [&](double s) { return noise.eval(x * s, y * s, z * s); });
}
template <class Noise>
float fbm(const Noise& noise, double x, double y, const FractalParams& f) {
    return detail::octave_sum(f, [&](double s) { return noise.eval(x * s, y * s); });
}

/// Perlin's turbulence: the octave sum of |noise|, normalised to [0, 1].
template <class Noise>
float turbulence(const Noise& noise, double x, double y, double z, const FractalParams& f) {
    return detail::octave_sum(f, [&](double s) { return std::abs(noise.eval(x * s, y * s, z * s)); });
}
template <class Noise>
float turbulence(const Noise& noise, double x, double y, const FractalParams& f) {
    return detail::octave_sum(f, [&](double s) { return std::abs(noise.eval(x * s, y * s)); });
}

}  // namespace rtlab
