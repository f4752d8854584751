#pragma once
/// \brief Tone reproduction: HDR radiance to display values in [0, 1], created by name.
#include <rtlab/core/image.hpp>
#include <rtlab/core/registry.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace rtlab {

/// \brief What an operator measured and used; reported to the user.
struct ToneReport {
    double log_average = 0.0;        ///< exp(mean(log(delta + L))) over finite pixels, delta = 1e-4
    double max_luminance = 0.0;      ///< over finite pixels
    std::size_t invalid_pixels = 0;  ///< NaN or infinite pixels: left out of the statistics, written black
    double scale = 1.0;              ///< the operator's scale factor (m for Ward, a / L_avg for Reinhard, 2^stops)
    std::string summary;             ///< one line naming the operator and its parameters
};

/// \brief A global tone operator. apply() returns linear display values clamped to [0, 1], finite for
/// any input; sRGB encoding happens once, when the result is written (rtlab::write_png).
class ToneOperator {
public:
    virtual ~ToneOperator() = default;
    virtual Image apply(const Image& hdr, ToneReport* report = nullptr) const = 0;
};

using ToneRegistry = Registry<ToneOperator>;

/// Registers "ward", "reinhard", "exposure" and "aces" with their documented parameters.
void register_builtins(ToneRegistry& registry);
/// A registry holding the built-ins.
ToneRegistry make_tone_registry();

/// \brief Luminance statistics of an image (Rec. 709 luminance of linear RGB).
struct LuminanceStats {
    double log_average = 0.0;
    double max_luminance = 0.0;
    std::size_t invalid_pixels = 0;
};
/// NaN and infinite pixels are counted and skipped; negative components count as 0.
LuminanceStats measure_luminance(const Image& hdr, double delta = 1e-4);

}  // namespace rtlab
